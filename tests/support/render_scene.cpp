#include "support/render_scene.h"
#include "support/option_names.h"

#include "core/accel/embree_accel.h"
#include "integrators/render.h"

namespace penumbra::test {

SceneRender render_scene(const Scene& scene, const Camera& camera, const std::string& integrator,
                         uint32_t spp, uint64_t seed, int max_depth,
                         std::unique_ptr<EnvironmentLight> environment) {
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, std::move(environment));
    const RenderContext ctx{scene, accel, lights};
    IntegratorOptions iopt;
    iopt.max_depth = max_depth;
    const auto integ = make_integrator(test::integrator_named(integrator), iopt);
    RenderOptions opt;
    opt.spp = spp;
    opt.seed = seed;
    opt.progress = false;
    opt.filter = FilterType::Box;
    RenderStats stats;
    SceneRender out;
    out.image = render(ctx, camera, *integ, opt, &stats).resolve();
    out.nonfinite_samples = stats.nonfinite_samples;
    return out;
}

void transform_scene(Scene& scene, const Transform& xf) {
    for (Instance& inst : scene.instances) {
        inst.to_world = xf * inst.to_world;
        for (Transform& m : inst.motion) m = xf * m;
    }
    for (CameraDesc& cam : scene.cameras) {
        cam.to_world = xf * cam.to_world;
        for (Transform& m : cam.motion) m = xf * m;
    }
}

float pixel_mean(const Image& img, int x, int y) {
    const float* p = img.at(x, y);
    return (p[0] + p[1] + p[2]) / 3;
}

}  // namespace penumbra::test
