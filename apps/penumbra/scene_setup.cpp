#include "apps/penumbra/scene_setup.h"

#include "apps/penumbra/light_check.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <stdexcept>

#include "core/camera/autofocus.h"
#include "core/camera/default_camera.h"
#include "core/camera/thin_lens_camera.h"
#include "core/error.h"
#include "core/lights/default_lights.h"
#include "core/log.h"
#include "core/progress.h"
#include "core/scene/scene_stats.h"
#include "io/gltf/gltf_asset.h"
#include "io/image/image_reader.h"
#include "io/color/scene_color.h"
#include "materials/material.h"
#include "job/aov_list.h"

namespace penumbra {

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

// Environment images and colours are taken as linear Rec.709, like glTF's colours.
std::unique_ptr<EnvironmentLight> make_environment(const EnvironmentOptions& e,
                                                   const Scene& scene,
                                                   const Mat3& rec709_to_working,
                                                   EnvironmentSampling sampling) {
    if (!e.image.empty()) {
        Image img = read_image(e.image, ImageEncoding::Linear);
        convert_image_colors(img, rec709_to_working);
        return std::make_unique<EnvironmentLight>(std::move(img), e.intensity, e.rotation,
                                                  scene_radius(scene), sampling);
    }
    if (e.color.size() == 3)
        return std::make_unique<EnvironmentLight>(
            rec709_to_working * Spectrum(e.color[0], e.color[1], e.color[2]) * e.intensity,
            scene_radius(scene));
    return nullptr;
}

// Command-line depth of field settings override the file's; focusing on a pixel needs
// the accelerator, so this runs after it is built.
void apply_lens_options(const LensOverrides& o, const std::string& path, int width,
                        int height, const Scene& scene, const Accel& accel, CameraDesc& cam) {
    if (o.aperture_blades >= 0) cam.aperture_blades = o.aperture_blades;
    if (o.aperture_radius >= 0) cam.aperture_radius = o.aperture_radius;
    if (o.fstop > 0) cam.aperture_radius = aperture_radius_from_fstop(o.fstop, cam.yfov,
                                                                      cam.sensor_height_mm);
    if (o.focus_distance > 0) cam.focus_distance = o.focus_distance;
    if (o.focus_on.size() == 2) {
        const std::optional<float> d =
            focus_distance_at(cam, width, height, o.focus_on[0], o.focus_on[1], scene, accel);
        if (!d)
            throw SceneError(path + ": --focus-on " + std::to_string(o.focus_on[0]) + " " +
                             std::to_string(o.focus_on[1]) + ": no surface behind that pixel");
        cam.focus_distance = *d;
        LOG_INFO(path << ": focus distance " << *d << " (surface at pixel " << o.focus_on[0]
                      << " " << o.focus_on[1] << ")");
    }
    if (cam.aperture_radius > 0 && !(cam.focus_distance > 0))
        throw SceneError(path + ": depth of field needs a focus distance (--focus-distance "
                                "or --focus-on)");
    if (cam.aperture_radius > 0 && cam.type == ProjectionType::Orthographic)
        throw SceneError(path + ": depth of field needs a perspective camera");
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// Poses the source's file (loaded first when it is not yet) at the options' shutter into
// s.scene, and reports what its textures cost.
GltfLoadStats load_scene(const RenderCommandOptions& o, SceneSource& source, SceneSetup& s) {
    std::unique_ptr<GltfAsset>& asset = source.asset;
    const std::string& path = s.path;
    const auto t0 = Clock::now();
    ShutterInterval shutter;
    try {
        shutter = resolve_shutter(o.timeline);
    } catch (const std::invalid_argument& e) {
        throw SceneError(path + ": " + e.what());
    }
    if (!asset) {
        GltfLoadOptions load = o.gltf;
        load.rec709_to_working = s.color->rec709_to_working();
        // Motion vectors reach one frame to each side.
        if (parse_aovs(o.aovs).has(Aov::Vector)) load.neighbour_frame_offset = 1 / o.timeline.fps;
        asset = std::make_unique<GltfAsset>(path, load);
    }
    GltfLoadStats load_stats;
    s.scene = asset->scene_at(shutter.open, shutter.close, &load_stats);
    s.load_seconds = since(t0);
    Scene& scene = s.scene;
    if (o.no_file_lights && !scene.lights.empty()) {
        LOG_INFO(path << ": " << scene.lights.size()
                      << " punctual light(s) of the file left out (--no-file-lights)");
        scene.lights.clear();
    }
    s.file_lights = scene.lights.size();
    if (!scene.images.empty()) {
        // What the texture store costs (docs/performance.md), pyramids included.
        double bytes = 0, texels = 0;
        for (const TextureImage& img : scene.images) {
            bytes += double(img.bytes());
            texels += double(img.texel_count());
        }
        LOG_INFO(path << ": textures: " << scene.images.size() << " images, " << texels / 1e6
                      << " Mtexels, " << bytes / (1 << 20) << " MiB with mipmaps ("
                      << bytes / texels << " B/texel)");
    }
    return load_stats;
}

// Image size: what the user asked, completed from the camera's aspect ratio.
void choose_camera_and_size(const RenderCommandOptions& o, SceneSetup& s) {
    const Scene& scene = s.scene;
    // The views (--views) replace the file's cameras.
    const CameraDesc* file_cam = nullptr;
    if (o.views.empty() && !o.camera.empty())
        file_cam = find_camera(scene, o.camera);
    else if (o.views.empty() && !scene.cameras.empty())
        file_cam = &scene.cameras[0];
    float aspect = file_cam && file_cam->aspect_ratio > 0 ? file_cam->aspect_ratio
                   : file_cam && file_cam->type == ProjectionType::Orthographic
                       ? file_cam->xmag / file_cam->ymag
                       : 4.0f / 3.0f;
    if (o.width && o.height) aspect = float(o.width) / float(o.height);
    s.width = o.width ? o.width
                      : (o.height ? std::max(1, int(std::lround(o.height * aspect))) : 640);
    s.height = o.height ? o.height : std::max(1, int(std::lround(s.width / aspect)));
    s.camera_desc = file_cam ? *file_cam : default_camera(scene.bounds(), aspect);
    s.file_camera = file_cam ? int(file_cam - scene.cameras.data()) : -1;
    if (!file_cam && o.views.empty())
        LOG_INFO(s.path << ": no camera in the file; using one that frames the scene");
}

// What setup_lights decided that the view check after the accelerator needs again.
struct LightingSetup {
    DefaultLightMode mode = DefaultLightMode::Auto;
    LightSetOptions options;
};

// The environment, the default lights when the scene needs them, and the light set.
// Runs after the integrator: how the environment is sampled depends on it.
LightingSetup setup_lights(const RenderCommandOptions& o, SceneSetup& s) {
    const std::string& path = s.path;
    Scene& scene = s.scene;
    const bool paired = s.integrator->pairs_light_and_bsdf_samples();
    const EnvSamplingChoice sampling = o.env.sampling;
    if (sampling == EnvSamplingChoice::Compensated && !paired)
        throw SceneError(path +
                         ": --env-sampling compensated needs every light sample paired "
                         "with a BSDF sample by MIS (--integrator path with "
                         "--strategy mis, or direct with light and BSDF samples); "
                         "the image would be too dark otherwise");
    const bool compensate = sampling == EnvSamplingChoice::Compensated ||
                            (sampling == EnvSamplingChoice::Auto && paired);
    std::unique_ptr<EnvironmentLight> env = make_environment(
        o.env, scene, s.color->rec709_to_working(),
        compensate ? EnvironmentSampling::MisCompensated : EnvironmentSampling::Full);
    LightingSetup result;
    result.mode = o.default_light;
    const LightingChoice lighting = choose_lighting(result.mode, scene, env != nullptr);
    s.default_lights = lighting.add_defaults;
    LOG_INFO(path << ": lighting: " << lighting.reason);
    if (lighting.add_defaults) {
        std::unique_ptr<EnvironmentLight> dim = add_default_lights(scene, s.camera_desc);
        if (!env) env = std::move(dim);
    }
    result.options = o.lights;
    s.lights = std::make_unique<LightSet>(scene, std::move(env), result.options);
    return result;
}

// Builds the accelerator, or takes the source's last one where nothing moved, and reports
// where load and build time and memory go, for big scenes (docs/performance.md).
void build_accel(const RenderCommandOptions& o, const GltfLoadStats& ls, SceneSource& source,
                 SceneSetup& s) {
    const Scene& scene = s.scene;
    const auto t0 = Clock::now();
    const std::clock_t build_cpu = std::clock();
    s.accel = source.reuse_accel(scene);
    // Only a later frame's pose reads the parsed file again; without one it goes before the
    // build, as after a single load.
    if (!source.more_frames) source.asset.reset();
    if (s.accel)
        LOG_INFO(s.path << ": the previous frame's accelerator kept: nothing moved");
    else
        s.accel = make_accel(o.accel, scene);
    s.build_seconds = since(t0);
    const AccelStats as = s.accel->stats();
    char line[400];
    std::snprintf(line, sizeof(line),
                  "parse %.3f s (cpu %.3f), meshes %.3f (%.3f), materials %.3f (%.3f), nodes "
                  "%.3f (%.3f); %s build %.3f s (cpu %.3f); %zu triangles in %s of meshes, "
                  "%zu images, %s %s; peak memory %s",
                  ls.parse.seconds, ls.parse.cpu_seconds, ls.meshes.seconds, ls.meshes.cpu_seconds,
                  ls.materials.seconds, ls.materials.cpu_seconds, ls.nodes.seconds,
                  ls.nodes.cpu_seconds, as.name.c_str(), s.build_seconds,
                  double(std::clock() - build_cpu) / CLOCKS_PER_SEC, unique_triangle_count(scene),
                  format_bytes(mesh_memory_bytes(scene)).c_str(), scene.images.size(),
                  as.name.c_str(), format_bytes(as.memory_bytes).c_str(),
                  format_bytes(peak_memory_bytes()).c_str());
    // A frame after the first of a file only poses it: no parse, no image decoding.
    LOG_INFO(s.path << (ls.parsed ? ": load and build: " : ": pose and build: ") << line);
}

// The motion vectors' cameras for the camera just chosen: a file camera's own poses at the
// neighbouring frames; views and the automatic camera stand still.
void set_motion_cameras(SceneSetup& s) {
    if (!s.scene.frame_neighbours) return;
    const FrameNeighbours& n = *s.scene.frame_neighbours;
    const size_t c = size_t(s.file_camera);
    const bool file = s.file_camera >= 0;
    s.motion_cameras = motion_vector_cameras(s.camera_desc, file ? &n.previous.cameras[c] : nullptr,
                                             file ? &n.next.cameras[c] : nullptr, s.width,
                                             s.height);
}

}  // namespace

RenderContext SceneSetup::context() const {
    RenderContext ctx{scene, *accel, *lights, scene_has_alpha(scene), materials};
    if (motion_cameras) ctx.motion_vectors = &*motion_cameras;
    return ctx;
}

std::unique_ptr<SceneSetup> setup_scene(const RenderCommandOptions& o, const std::string& path) {
    SceneSource source;
    return setup_scene(o, path, source);
}

std::unique_ptr<SceneSetup> setup_scene(const RenderCommandOptions& o, const std::string& path,
                                        SceneSource& source) {
    auto s = std::make_unique<SceneSetup>();
    s->path = path;
    s->color = std::make_unique<ColorPipeline>(o.color);
    const GltfLoadStats load_stats = load_scene(o, source, *s);
    choose_camera_and_size(o, *s);
    s->integrator = make_integrator(o.integrator, o.path);
    const LightingSetup lighting = setup_lights(o, *s);
    build_accel(o, load_stats, source, *s);

    apply_lens_options(o.lens, path, s->width, s->height, s->scene, *s->accel, s->camera_desc);

    s->camera = make_camera(s->camera_desc, s->width, s->height);
    set_motion_cameras(*s);
    s->materials = o.materials;
    // What the camera sees decides too: the file's lights can pass the rule in
    // setup_lights and still leave the view dark (a filament inside its lamp, watts
    // written as candela).
    if (lighting.mode == DefaultLightMode::Auto && !s->default_lights &&
        !s->lights->environment())
        add_default_lights_if_view_dark(*s, o, lighting.options);
    return s;
}

void use_view(SceneSetup& s, size_t index, const RenderCommandOptions& o) {
    s.camera_desc = s.views.at(index);
    s.file_camera = -1;
    apply_lens_options(o.lens, s.path, s.width, s.height, s.scene, *s.accel, s.camera_desc);
    s.camera = make_camera(s.camera_desc, s.width, s.height);
    set_motion_cameras(s);
}

RenderOptions render_options_for(const RenderCommandOptions& o, const std::string& label) {
    RenderOptions r;
    r.spp = o.spp;
    r.seed = o.seed;
    r.threads = o.threads;
    r.sampler = o.sampler;
    r.filter = o.filter;
    r.progress = !o.quiet;
    r.label = label;
    r.time = resolve_shutter(o.timeline).open;
    r.time_limit = o.time_limit;
    r.aovs = parse_aovs(o.aovs);
    if (o.denoise) r.aovs.add(Aov::Denoise);
    // The integrator leaves escaped camera rays black; the film's alpha says where.
    if (o.path.transparent_background) r.aovs.add(Aov::Coverage);
    r.target_error = o.target_error;
    r.min_spp = o.adaptive_min_spp;
    return r;
}

}  // namespace penumbra
