#include "apps/penumbra/render_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "core/accel/accel.h"
#include "core/camera/default_camera.h"
#include "core/error.h"
#include "core/lights/directional_light.h"
#include "core/lights/light_set.h"
#include "core/log.h"
#include "core/progress.h"
#include "integrators/render.h"
#include "io/gltf_loader.h"
#include "io/image_reader.h"
#include "io/image_writer.h"
#include "materials/material.h"

namespace penumbra {

namespace fs = std::filesystem;

void add_render_command(CLI::App& app, RenderCommandOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "render", "Render glTF scenes to linear EXR images (plus a PNG preview)");
    cmd->add_option("scenes", o.scenes, "Scene files (.gltf or .glb)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", o.output,
                    "Output EXR (one scene only); default: OUT_DIR/<scene>.exr");
    cmd->add_option("--out-dir", o.out_dir, "Folder for outputs when -o is not given")
        ->capture_default_str();
    cmd->add_flag("--no-preview", o.no_preview, "Do not write the sRGB PNG preview");
    cmd->add_option("--width", o.width,
                    "Image width in pixels (default 640, or from --height and the camera's "
                    "aspect ratio)")
        ->check(CLI::Range(1, 1 << 15));
    cmd->add_option("--height", o.height,
                    "Image height in pixels (default: from the width and the camera's aspect "
                    "ratio, else 4:3)")
        ->check(CLI::Range(1, 1 << 15));
    cmd->add_option("--spp", o.spp, "Samples per pixel")->capture_default_str()->check(
        CLI::Range(1u, 1u << 24));
    cmd->add_option("--threads", o.threads, "Worker threads (0: all cores)")
        ->capture_default_str()
        ->check(CLI::Range(0, 4096));
    cmd->add_option("--seed", o.seed, "Random seed; the same seed gives the same image")
        ->capture_default_str();
    cmd->add_option("--camera", o.camera,
                    "Camera by name or index (default: the first camera in the file, else "
                    "one framing the whole scene)");
    std::string integrator_help = "Integrator:";
    std::vector<std::string> integrator_list;
    for (const auto& [name, desc] : integrator_names()) {
        integrator_help += "\n  " + name + ": " + desc;
        integrator_list.push_back(name);
    }
    cmd->add_option("--integrator", o.integrator, integrator_help)
        ->capture_default_str()
        ->check(CLI::IsMember(integrator_list));
    cmd->add_option("--sampler", o.sampler, "Pixel sampler")
        ->capture_default_str()
        ->check(CLI::IsMember({"independent", "stratified", "sobol"}));
    cmd->add_option("--filter", o.filter, "Pixel reconstruction filter")
        ->capture_default_str()
        ->check(CLI::IsMember({"box", "gaussian", "blackman-harris"}));
    cmd->add_option("--accel", o.accel, "Ray intersection accelerator")
        ->capture_default_str()
        ->check(CLI::IsMember(
            {"embree", "bvh", "bvh-sah", "bvh-median", "bvh-center", "grid"}));
    cmd->add_option("--strategy", o.strategy,
                    "path: estimators for area and environment light: mis (both, combined), "
                    "bsdf (BSDF sampling only) or light (light sampling only)")
        ->capture_default_str()
        ->check(CLI::IsMember({"mis", "bsdf", "light"}));
    cmd->add_option("--light-samples", o.light_samples,
                    "direct: shadow rays per shading point")
        ->capture_default_str()
        ->check(CLI::Range(0, 1 << 16));
    cmd->add_option("--bsdf-samples", o.bsdf_samples, "direct: BSDF samples per shading point")
        ->capture_default_str()
        ->check(CLI::Range(0, 1 << 16));
    cmd->add_option("--max-depth", o.max_depth,
                    "path: maximum bounces; basic/direct: maximum specular recursion")
        ->capture_default_str()
        ->check(CLI::Range(0, 1024));
    cmd->add_option("--env", o.env,
                    "Environment: an equirectangular HDR/EXR image (+Y up), importance-sampled")
        ->check(CLI::ExistingFile);
    cmd->add_option("--env-color", o.env_color, "Environment: constant radiance R G B")
        ->expected(3);
    cmd->add_option("--env-intensity", o.env_intensity, "Scale of the environment radiance")
        ->capture_default_str();
    cmd->add_option("--env-rotation", o.env_rotation,
                    "Rotation of the environment image about +Y, in degrees")
        ->capture_default_str();
    cmd->add_flag("!--no-default-light", o.default_light,
                  "Do not light scenes that have no lights of their own (otherwise: a key "
                  "light and a dim uniform environment)");
    cmd->add_flag("-q,--quiet", o.quiet, "Only print errors");
}

namespace {

const CameraDesc* find_camera(const Scene& scene, const std::string& wanted) {
    for (const CameraDesc& c : scene.cameras)
        if (c.name == wanted) return &c;
    char* end = nullptr;
    const long index = std::strtol(wanted.c_str(), &end, 10);
    if (!wanted.empty() && end && *end == '\0' && index >= 0 &&
        index < static_cast<long>(scene.cameras.size()))
        return &scene.cameras[index];
    std::string names;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i) + " '" + scene.cameras[i].name + "'";
    throw SceneError(scene.source + ": no camera '" + wanted + "' (the file has " +
                     (names.empty() ? std::string("no cameras") : names) + ")");
}

float scene_radius(const Scene& scene) {
    const Bounds3 b = scene.bounds();
    return b.empty() ? 1.0f : std::max(0.5f * length(b.diagonal()), 1e-3f);
}

// Scenes exported without lights would render black: light them like a product shot,
// a key light from the upper right of the camera and a dimmer fill from the left.
void add_default_lights(Scene& scene, const CameraDesc& cam) {
    const float radius = scene_radius(scene);
    const Transform& xf = cam.to_world;
    const Vec3 key = normalize(xf.vector(Vec3(-0.5f, -0.7f, -1.0f)));
    const Vec3 fill = normalize(xf.vector(Vec3(0.8f, -0.2f, -1.0f)));
    scene.lights.push_back(std::make_unique<DirectionalLight>(key, Spectrum(2.5f), radius));
    scene.lights.push_back(std::make_unique<DirectionalLight>(fill, Spectrum(0.6f), radius));
}

std::unique_ptr<EnvironmentLight> make_environment(const RenderCommandOptions& o,
                                                   const Scene& scene) {
    if (!o.env.empty())
        return std::make_unique<EnvironmentLight>(read_image(o.env, ImageEncoding::Linear),
                                                  o.env_intensity, o.env_rotation,
                                                  scene_radius(scene));
    if (o.env_color.size() == 3)
        return std::make_unique<EnvironmentLight>(
            Spectrum(o.env_color[0], o.env_color[1], o.env_color[2]) * o.env_intensity,
            scene_radius(scene));
    return nullptr;
}

bool has_emission(const Scene& scene) {
    for (const MaterialDesc& m : scene.materials)
        if (m.is_emissive()) return true;
    return false;
}

std::string output_for(const RenderCommandOptions& o, const std::string& scene_path) {
    if (!o.output.empty()) return o.output;
    return (fs::path(o.out_dir) / fs::path(scene_path).stem()).string() + ".exr";
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

void render_one(const RenderCommandOptions& o, const std::string& path) {
    const std::string output = output_for(o, path);

    auto t0 = Clock::now();
    Scene scene = load_gltf(path);
    const double load_s = since(t0);

    // Image size: what the user asked, completed from the camera's aspect ratio.
    const CameraDesc* file_cam = nullptr;
    if (!o.camera.empty())
        file_cam = find_camera(scene, o.camera);
    else if (!scene.cameras.empty())
        file_cam = &scene.cameras[0];
    float aspect = file_cam && file_cam->aspect_ratio > 0 ? file_cam->aspect_ratio
                   : file_cam && file_cam->type == ProjectionType::Orthographic
                       ? file_cam->xmag / file_cam->ymag
                       : 4.0f / 3.0f;
    if (o.width && o.height) aspect = float(o.width) / float(o.height);
    const int width = o.width ? o.width : (o.height ? std::max(1, int(std::lround(o.height * aspect))) : 640);
    const int height = o.height ? o.height : std::max(1, int(std::lround(width / aspect)));
    const CameraDesc cam_desc = file_cam ? *file_cam : default_camera(scene.bounds(), aspect);
    if (!file_cam) LOG_INFO(path << ": no camera in the file; using one that frames the scene");
    std::unique_ptr<EnvironmentLight> env = make_environment(o, scene);
    if (scene.lights.empty() && !has_emission(scene) && !env && o.default_light) {
        LOG_INFO(path << ": no lights in the file; adding a key light and a dim environment "
                         "(--no-default-light to disable)");
        add_default_lights(scene, cam_desc);
        env = std::make_unique<EnvironmentLight>(Spectrum(0.3f), scene_radius(scene));
    }
    const LightSet lights(scene, std::move(env));

    t0 = Clock::now();
    const std::unique_ptr<Accel> accel = make_accel(parse_accel_type(o.accel), scene);
    const double build_s = since(t0);

    IntegratorOptions iopt;
    iopt.max_depth = o.max_depth;
    iopt.strategy = parse_light_strategy(o.strategy);
    iopt.light_samples = o.light_samples;
    iopt.bsdf_samples = o.bsdf_samples;
    const std::unique_ptr<Integrator> integrator = make_integrator(o.integrator, iopt);
    const std::unique_ptr<Camera> camera = make_camera(cam_desc, width, height);

    RenderOptions ropt;
    ropt.spp = o.spp;
    ropt.seed = o.seed;
    ropt.threads = o.threads;
    ropt.sampler = parse_sampler_type(o.sampler);
    ropt.filter = o.filter;
    ropt.progress = !o.quiet;
    ropt.label = fs::path(path).filename().string();
    RenderStats stats;
    const RenderContext ctx{scene, *accel, lights, scene_has_alpha(scene)};
    const Film film = render(ctx, *camera, *integrator, ropt, &stats);

    t0 = Clock::now();
    const Image image = film.resolve();
    const Metadata metadata = {
        {"Software", std::string("penumbra ") + PENUMBRA_VERSION},
        {"penumbra:scene", path},
        {"penumbra:camera", cam_desc.name},
        {"penumbra:integrator", o.integrator},
        {"penumbra:strategy", o.strategy},
        {"penumbra:max_depth", std::to_string(o.max_depth)},
        {"penumbra:accelerator", o.accel},
        {"penumbra:sampler", o.sampler},
        {"penumbra:filter", o.filter},
        {"penumbra:spp", std::to_string(o.spp)},
        {"penumbra:seed", std::to_string(o.seed)},
        {"penumbra:rays", std::to_string(stats.rays)},
        {"penumbra:nonfinite_samples", std::to_string(stats.nonfinite_samples)},
    };
    write_exr(output, image, metadata);
    std::string preview;
    if (!o.no_preview) {
        preview = preview_path_for(output);
        write_preview(preview, image);
    }
    const double write_s = since(t0);

    if (!o.quiet) {
        const AccelStats as = accel->stats();
        std::fprintf(stderr,
                     "%s -> %s%s%s\n"
                     "  %dx%d, %u spp, integrator %s, camera '%s'\n"
                     "  load %s, build %s (%zu meshes, %zu instances), render %s, write %s\n"
                     "  %.2f M rays/s (%llu rays), %.2f M samples/s, peak memory %s%s\n",
                     path.c_str(), output.c_str(), preview.empty() ? "" : " + ",
                     preview.c_str(), width, height, o.spp, o.integrator.c_str(),
                     cam_desc.name.c_str(), format_duration(load_s).c_str(),
                     format_duration(build_s).c_str(), as.object_scenes, as.instances,
                     format_duration(stats.seconds).c_str(), format_duration(write_s).c_str(),
                     stats.seconds > 0 ? stats.rays / stats.seconds / 1e6 : 0.0,
                     static_cast<unsigned long long>(stats.rays),
                     stats.seconds > 0 ? stats.camera_samples / stats.seconds / 1e6 : 0.0,
                     format_bytes(peak_memory_bytes()).c_str(),
                     stats.nonfinite_samples
                         ? (", " + std::to_string(stats.nonfinite_samples) +
                            " NaN/Inf samples discarded")
                               .c_str()
                         : "");
    }
}

}  // namespace

int run_render_command(const RenderCommandOptions& o) {
    if (o.quiet) set_log_level(LogLevel::Error);
    if (!o.output.empty() && o.scenes.size() > 1)
        throw SceneError("-o names one file, but " + std::to_string(o.scenes.size()) +
                         " scenes were given; use --out-dir instead");
    int failed = 0;
    for (const std::string& path : o.scenes) {
        try {
            render_one(o, path);
        } catch (const std::exception& e) {
            // One bad scene does not stop the batch.
            std::fprintf(stderr, "error: %s\n", e.what());
            ++failed;
        }
    }
    if (failed && o.scenes.size() > 1)
        std::fprintf(stderr, "%d of %zu scenes failed\n", failed, o.scenes.size());
    return failed ? 1 : 0;
}

}  // namespace penumbra
