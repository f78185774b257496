#include "apps/penumbra/study/check_accel_command.h"

#include "apps/penumbra/option_cli.h"

#include <CLI/CLI.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "study/accel_check.h"
#include "core/accel/embree_accel.h"
#include "core/camera/default_camera.h"
#include "core/lights/light_set.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "integrators/render.h"
#include "io/gltf/gltf_loader.h"
#include "materials/material.h"

namespace penumbra {

void add_check_accel_command(CLI::App& app, CheckAccelOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "check-accel",
        "Trace the same rays through every accelerator (embree, bvh-sah, bvh-median, "
        "bvh-center, grid) and report agreement with Embree, build time, memory and speed");
    cmd->add_option("scene", o.scene, "Scene file (.gltf or .glb)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--rays", o.rays, "Random, shadow and bounce rays, each")
        ->capture_default_str()
        ->check(CLI::Range(size_t(0), size_t(1) << 30));
    cmd->add_option("--seed", o.seed, "Random seed of the rays")->capture_default_str();
    cmd->add_option("--threshold", o.threshold,
                    "Fail when more than this fraction of the rays disagree with Embree")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--width", o.width, "Camera rays: an image this wide (and --images)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 13));
    cmd->add_flag("--images", o.images,
                  "Also render with each accelerator (basic integrator, same samples) and "
                  "compare the images with Embree's");
    cmd->add_option("--spp", o.spp, "Samples per pixel for --images")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1u << 16));
    cmd->add_option("--embree-isa", o.embree_isas,
                    "Also check Embree under these instruction sets against its default "
                    "(sse4.2, avx2, avx512; Embree's device config isa=...)")
        ->delimiter(',');
    add_declared_options(cmd, o.timing, is_timeline_option);
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// Million rays per second of intersect() over all rays: single-threaded (best of two
// passes, the first warms the caches) or with every TBB thread.
double mrays_per_second(const Accel& accel, const std::vector<CheckRay>& rays, bool parallel) {
    double best = 1e30;
    for (int pass = 0; pass < 2; ++pass) {
        const auto t0 = Clock::now();
        if (parallel) {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256),
                              [&](const tbb::blocked_range<size_t>& r) {
                                  size_t hits = 0;
                                  for (size_t i = r.begin(); i != r.end(); ++i)
                                      hits += accel.intersect(rays[i].ray).has_value();
                                  volatile size_t sink = hits;
                                  (void)sink;
                              });
        } else {
            size_t hits = 0;
            for (const CheckRay& r : rays) hits += accel.intersect(r.ray).has_value();
            volatile size_t sink = hits;
            (void)sink;
        }
        best = std::min(best, since(t0));
    }
    return best > 0 ? rays.size() / best / 1e6 : 0;
}

struct ImageDiff {
    size_t differing = 0;  // pixels where any channel differs
    double max_abs = 0, mean_abs = 0;
};

ImageDiff diff_images(const Image& a, const Image& b) {
    ImageDiff d;
    double sum = 0;
    const size_t pixels = size_t(a.width) * a.height;
    for (size_t p = 0; p < pixels; ++p) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const double e = std::abs(double(a.pixels[p * a.channels + c]) -
                                      double(b.pixels[p * b.channels + c]));
            differs = differs || e > 0;
            d.max_abs = std::max(d.max_abs, e);
            sum += e;
        }
        d.differing += differs;
    }
    d.mean_abs = pixels ? sum / (3.0 * pixels) : 0;
    return d;
}

bool has_emission(const Scene& scene) {
    for (const MaterialDesc& m : scene.materials)
        if (m.is_emissive()) return true;
    return false;
}

float scene_radius(const Scene& scene) {
    const Bounds3 b = scene.bounds();
    return b.empty() ? 1.0f : std::max(0.5f * length(b.diagonal()), 1e-3f);
}

// Renders with each accelerator, the same seed and samples, and prints an idiff-style
// summary against Embree's image.
void compare_images(const Scene& scene, const CameraDesc& cam_desc, int width, int height,
                    unsigned spp, const std::vector<std::unique_ptr<Accel>>& accels,
                    const std::vector<std::string>& names) {
    // Scenes without lights get a uniform white sky, so the images are not all black.
    std::unique_ptr<EnvironmentLight> env;
    if (scene.lights.empty() && !has_emission(scene))
        env = std::make_unique<EnvironmentLight>(Spectrum(1.0f), scene_radius(scene));
    const LightSet lights(scene, std::move(env));
    const std::unique_ptr<Integrator> integrator = make_integrator(IntegratorType::Basic, {});
    const std::unique_ptr<Camera> camera = make_camera(cam_desc, width, height);
    RenderOptions ropt;
    ropt.spp = spp;
    ropt.seed = 1;
    ropt.progress = false;
    std::vector<Image> images;
    for (const auto& accel : accels) {
        const RenderContext ctx{scene, *accel, lights, scene_has_alpha(scene)};
        images.push_back(render(ctx, *camera, *integrator, ropt).resolve());
    }
    std::printf("\nimages: %dx%d, basic integrator, %u spp, seed 1; differences from %s\n", width,
                height, spp, names[0].c_str());
    std::printf("  %-12s %16s %12s %12s\n", "accelerator", "pixels differ", "max |diff|",
                "mean |diff|");
    for (size_t i = 1; i < accels.size(); ++i) {
        const ImageDiff d = diff_images(images[0], images[i]);
        std::printf("  %-14s %9zu %5.2f%% %12.4g %12.4g\n", names[i].c_str(),
                    d.differing, 100.0 * d.differing / (double(width) * height), d.max_abs,
                    d.mean_abs);
    }
}

// Every accelerator type, then Embree once per ISA asked for; names[i] names accels[i].
std::vector<std::unique_ptr<Accel>> build_accels(const Scene& scene,
                                                 const std::vector<std::string>& embree_isas,
                                                 std::vector<std::string>& names) {
    std::vector<std::unique_ptr<Accel>> accels;
    names.clear();
    for (const AccelType type : all_accel_types()) {
        accels.push_back(make_accel(type, scene));
        names.push_back(accel_type_name(type));
    }
    for (const std::string& isa : embree_isas) {
        EmbreeBuildOptions eo;
        eo.device_config = "isa=" + isa;
        accels.push_back(std::make_unique<EmbreeAccel>(scene, eo));
        names.push_back("embree-" + isa);
    }
    return accels;
}

// Build time, memory and tracing speed of each accelerator, on one thread and on all.
void print_speed_table(const std::vector<std::unique_ptr<Accel>>& accels,
                       const std::vector<std::string>& names, const std::vector<CheckRay>& rays) {
    const int threads = tbb::this_task_arena::max_concurrency();
    std::printf("\n  %-14s %10s %12s %14s %16s\n", "accelerator", "build", "memory",
                "Mrays/s 1 thr", ("Mrays/s " + std::to_string(threads) + " thr").c_str());
    for (size_t i = 0; i < accels.size(); ++i) {
        const Accel& accel = *accels[i];
        const AccelStats st = accel.stats();
        const double single = mrays_per_second(accel, rays, false);
        const double multi = mrays_per_second(accel, rays, true);
        std::printf("  %-14s %8.2f ms %12s %14.2f %16.2f\n", names[i].c_str(),
                    st.build_seconds * 1e3, format_bytes(st.memory_bytes).c_str(), single, multi);
    }
}

// Compares every accelerator's hits with the first's and prints the table and the first
// disagreements; true when each stays within threshold.
bool check_agreement(const Scene& scene, const std::vector<CheckRay>& rays,
                     const std::vector<std::unique_ptr<Accel>>& accels,
                     const std::vector<std::string>& names, double threshold) {
    const TraceResults reference = trace_rays(*accels[0], rays);
    const std::string ref_name = names[0];
    std::printf(
        "\nagreement with %s: hit/miss, instance+mesh+prim, t within %g relative "
        "+ %g eps M/(|d| |cos|) (M: coordinate magnitude), barycentric points within "
        "that along the ray + %g of the longest edge\n",
        ref_name.c_str(), double(kCheckTRelTolerance), double(kCheckTUlps),
        double(kCheckBaryTolerance));
    std::printf("  %-14s %10s %10s %12s %9s %11s %7s %13s\n", "accelerator", "rays", "disagree",
                "edge/vertex", "grazing", "coincident", "other", "not identical");
    bool pass = true;
    std::vector<AgreementReport> reports;
    for (size_t i = 1; i < accels.size(); ++i) {
        const TraceResults res = trace_rays(*accels[i], rays);
        AgreementReport rep =
            compare_results(scene, rays, reference, res, ref_name, names[i]);
        std::printf("  %-14s %10llu %10llu %12llu %9llu %11llu %7llu %13llu\n", rep.name.c_str(),
                    (unsigned long long)rep.rays, (unsigned long long)rep.disagreements(),
                    (unsigned long long)rep.count(Disagreement::EdgeOrVertex),
                    (unsigned long long)rep.count(Disagreement::Grazing),
                    (unsigned long long)rep.count(Disagreement::Coincident),
                    (unsigned long long)rep.count(Disagreement::Other),
                    (unsigned long long)rep.not_identical);
        pass = pass && rep.passes(threshold);
        reports.push_back(std::move(rep));
    }
    for (const AgreementReport& rep : reports)
        if (rep.count(Disagreement::EdgeOrVertex))
            std::printf(
                "  %s: edge/vertex cases settled in double precision: %s right in "
                "%llu, %s right in %llu\n",
                rep.name.c_str(), ref_name.c_str(), (unsigned long long)rep.edge_reference_right,
                rep.name.c_str(), (unsigned long long)rep.edge_test_right);
    for (const AgreementReport& rep : reports) {
        if (rep.examples.empty()) continue;
        std::printf(
            "\n%s: first disagreements (by ray kind: %llu camera, %llu random, %llu "
            "shadow, %llu bounce)\n",
            rep.name.c_str(), (unsigned long long)rep.per_kind[0],
            (unsigned long long)rep.per_kind[1], (unsigned long long)rep.per_kind[2],
            (unsigned long long)rep.per_kind[3]);
        for (const std::string& e : rep.examples) std::printf("  %s\n", e.c_str());
    }
    return pass;
}

}  // namespace

int run_check_accel_command(const CheckAccelOptions& o) {
    set_log_level(LogLevel::Warning);
    GltfLoadOptions load;
    try {
        const ShutterInterval shutter = resolve_shutter(o.timing.timeline);
        load.shutter_open = shutter.open;
        load.shutter_close = shutter.close;
    } catch (const std::invalid_argument& e) {
        throw SceneError(o.scene + ": " + e.what());
    }
    const Scene scene = load_gltf(o.scene, load);
    const CameraDesc cam_desc =
        scene.cameras.empty() ? default_camera(scene.bounds(), 1.0f) : scene.cameras[0];
    const float aspect = cam_desc.aspect_ratio > 0 ? cam_desc.aspect_ratio
                         : cam_desc.type == ProjectionType::Orthographic
                             ? cam_desc.xmag / cam_desc.ymag
                             : 1.0f;
    const int width = o.width;
    const int height = std::max(1, int(std::lround(width / aspect)));

    std::vector<std::string> names;
    const std::vector<std::unique_ptr<Accel>> accels =
        build_accels(scene, o.embree_isas, names);

    const std::unique_ptr<Camera> camera = make_camera(cam_desc, width, height);
    CheckRayOptions ro;
    ro.random = ro.shadow = ro.bounce = o.rays;
    ro.seed = o.seed;
    const std::vector<CheckRay> rays = make_check_rays(scene, *camera, *accels[0], ro);
    size_t per_kind[kRayKinds] = {};
    for (const CheckRay& r : rays) ++per_kind[static_cast<int>(r.kind)];

    std::printf("%s: %zu triangles (%zu objects, %zu instances)\n", o.scene.c_str(),
                scene.triangle_count(), scene.objects.size(), scene.instances.size());
    std::printf(
        "rays: %zu camera (%dx%d, camera '%s'), %zu random, %zu shadow, %zu bounce; "
        "seed %llu\n",
        per_kind[0], width, height, cam_desc.name.c_str(), per_kind[1], per_kind[2], per_kind[3],
        o.seed);
    print_speed_table(accels, names, rays);

    const bool pass = check_agreement(scene, rays, accels, names, o.threshold);

    if (o.images) compare_images(scene, cam_desc, width, height, o.spp, accels, names);

    std::printf(
        "\n%s: %s (threshold: at most %g of the rays may disagree, coincident faces and "
        "edge cases where double precision shows the reference wrong aside, and none may be "
        "\"other\")\n",
        o.scene.c_str(), pass ? "PASS" : "FAIL", o.threshold);
    return pass ? 0 : 1;
}

}  // namespace penumbra
