#include "core/lights/default_lights.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "core/lights/directional_light.h"
#include "core/scene/emission.h"

namespace penumbra {

namespace {

// Thresholds of choose_lighting's rule.
constexpr double kMinMeanRadiance = (kDefaultKeyIrradiance + kDefaultFillIrradiance) / kPi;
constexpr double kMinPowerFraction = 0.01;

float scene_radius(const Scene& scene) {
    const Bounds3 b = scene.bounds();
    return b.empty() ? 1.0f : std::max(0.5f * length(b.diagonal()), 1e-3f);
}

std::string format(const char* fmt, double a, double b) {
    char buf[320];
    std::snprintf(buf, sizeof buf, fmt, a, b);
    return buf;
}

}  // namespace

double EmitterSummary::mean_radiance() const { return area > 0 ? power / (kPi * area) : 0; }

EmitterSummary summarize_emitters(const Scene& scene) {
    EmitterSummary s;
    // Mean emission per material, once: textures can be large.
    std::vector<double> mean_Le(scene.materials.size() + 1, -1.0);
    for (const Instance& inst : scene.instances) {
        for (uint32_t mi : scene.objects[inst.object].meshes) {
            const TriangleMesh& mesh = scene.meshes[mi];
            const MaterialDesc& mat = scene.material(mesh.material);
            if (!mat.is_emissive()) continue;
            double& Le = mean_Le[size_t(mesh.material + 1)];
            if (Le < 0)
                Le = luminance(mat.emissive * mat.emissive_strength *
                               mean_emission_texture(scene, mat));
            double area = 0;
            for (size_t t = 0; t < mesh.triangle_count(); ++t) {
                const Vec3 a = inst.to_world.point(mesh.positions[mesh.indices[3 * t]]);
                const Vec3 b = inst.to_world.point(mesh.positions[mesh.indices[3 * t + 1]]);
                const Vec3 c = inst.to_world.point(mesh.positions[mesh.indices[3 * t + 2]]);
                area += 0.5 * double(length(cross(b - a, c - a)));
            }
            s.area += area;
            s.power += kPi * area * std::max(Le, 0.0);
        }
    }
    return s;
}

LightingChoice choose_lighting(DefaultLightMode mode, const Scene& scene, bool has_environment) {
    if (mode == DefaultLightMode::Off)
        return {false, "the scene's own lights only (--default-light off)"};
    if (mode == DefaultLightMode::On)
        return {true, "default key and fill lights added (--default-light on)"};
    if (!scene.lights.empty())
        return {false, "the file's " + std::to_string(scene.lights.size()) + " light(s)"};
    if (has_environment) return {false, "the environment"};
    const EmitterSummary e = summarize_emitters(scene);
    if (e.area == 0)
        return {true,
                "no lights or emitters in the file: default key and fill lights and a "
                "dim environment (--default-light off to disable)"};
    const double R = scene_radius(scene);
    const double default_power =
        double(kDefaultKeyIrradiance + kDefaultFillIrradiance) * kPi * R * R;
    const double fraction = e.power / default_power;
    if (e.mean_radiance() < kMinMeanRadiance)
        return {true, format("emitters too dim to light the scene (mean radiance %.3g < %.3g): "
                             "default key and fill lights and a dim environment added "
                             "(--default-light off to disable)",
                             e.mean_radiance(), kMinMeanRadiance)};
    if (fraction < kMinPowerFraction)
        return {true, format("emitters too small to light the scene (%.3g W, %.2g%% of the "
                             "default lights' on it): default key and fill lights and a dim "
                             "environment added (--default-light off to disable)",
                             e.power, 100 * fraction)};
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "the file's emitters (%.3g W, %.2g%% of the default lights' on the scene; mean "
                  "radiance %.3g; --default-light on adds key and fill lights)",
                  e.power, 100 * fraction, e.mean_radiance());
    return {false, buf};
}

std::unique_ptr<EnvironmentLight> add_default_lights(Scene& scene, const CameraDesc& camera) {
    // Like a product shot: a key light from the upper right of the camera and a dimmer
    // fill from the left.
    const float radius = scene_radius(scene);
    const Transform& xf = camera.to_world;
    const Vec3 key = normalize(xf.vector(Vec3(-0.5f, -0.7f, -1.0f)));
    const Vec3 fill = normalize(xf.vector(Vec3(0.8f, -0.2f, -1.0f)));
    scene.lights.push_back(
        std::make_unique<DirectionalLight>(key, Spectrum(kDefaultKeyIrradiance), radius));
    scene.lights.push_back(
        std::make_unique<DirectionalLight>(fill, Spectrum(kDefaultFillIrradiance), radius));
    return std::make_unique<EnvironmentLight>(Spectrum(kDefaultEnvironmentRadiance), radius);
}

}  // namespace penumbra
