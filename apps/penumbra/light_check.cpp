#include "apps/penumbra/light_check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/camera/camera.h"
#include "core/film/film.h"
#include "core/lights/default_lights.h"
#include "core/log.h"
#include "integrators/render.h"

namespace penumbra {

namespace {

std::string percent(double fraction) {
    char buf[32];
    std::snprintf(buf, sizeof buf, fraction >= 0.1 ? "%.0f%%" : "%.2g%%", 100 * fraction);
    return buf;
}

std::string stops(double ev) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", ev);
    return buf;
}

std::string join(const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : "; ") + p;
    return out;
}

// Debug views (normals, albedo, depth, ...) show no light: their brightness says
// nothing about the lighting.
bool shows_light(IntegratorType integrator) {
    return integrator == IntegratorType::Path || integrator == IntegratorType::Direct ||
           integrator == IntegratorType::Basic;
}

bool user_environment(const RenderCommandOptions& o) {
    return !o.env.image.empty() || o.env.color.size() == 3;
}

}  // namespace

ImageExposure preview_exposure(const SceneSetup& setup, const RenderCommandOptions& o) {
    const double scale = std::min(
        1.0, std::sqrt(double(kPreviewPixels) / (double(setup.width) * double(setup.height))));
    const int w = std::max(1, int(std::lround(setup.width * scale)));
    const int h = std::max(1, int(std::lround(setup.height * scale)));
    const std::unique_ptr<Camera> camera = make_camera(setup.camera_desc, w, h);
    RenderOptions ropt;
    ropt.spp = kPreviewSpp;
    ropt.seed = 0;
    ropt.threads = o.threads;
    ropt.filter = o.filter;
    ropt.progress = false;
    Film film(w, h);
    render_samples(setup.context(), *camera, *setup.integrator, ropt, film, 0, kPreviewSpp);
    return measure_exposure(film.resolve(), o.exposure);
}

bool add_default_lights_if_view_dark(SceneSetup& setup, const RenderCommandOptions& o,
                                     const LightSetOptions& light_options) {
    if (!shows_light(o.integrator)) return false;
    const auto t0 = std::chrono::steady_clock::now();
    const ImageExposure e = preview_exposure(setup, o);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!e.nearly_black()) {
        char line[160];
        std::snprintf(line, sizeof line, "%s of a preview's %zu pixels lit, %.3f s",
                      percent(e.lit_fraction).c_str(), e.pixels, seconds);
        LOG_INFO(setup.path << ": the view is lit by the file's lights (" << line << ")");
        return false;
    }
    const std::string hint =
        light_units_hint(setup.scene.generator, setup.file_lights, o.gltf.light_units);
    LOG_WARNING(setup.path << ": the file's lights leave the view dark (" << percent(e.lit_fraction)
                           << " of a preview's pixels reach " << percent(kLitLuminance)
                           << " of display white, under " << percent(kMinLitFraction) << ")"
                           << (hint.empty() ? "" : "; likely cause: " + hint)
                           << "; default key and fill lights and a dim environment added "
                              "(--default-light off renders the file's lights alone)");
    std::unique_ptr<EnvironmentLight> dim = add_default_lights(setup.scene, setup.camera_desc);
    setup.lights = std::make_unique<LightSet>(setup.scene, std::move(dim), light_options);
    setup.default_lights = true;
    return true;
}

std::string light_units_hint(const std::string& generator, size_t file_lights,
                             LightUnits light_units) {
    if (file_lights == 0 || light_units != LightUnits::Photometric) return "";
    const std::string tag = "Blender I/O v";
    const size_t at = generator.find(tag);
    if (at == std::string::npos) return "";
    const long major = std::strtol(generator.c_str() + at + tag.size(), nullptr, 10);
    if (major != 1) return "";
    return "the file's lights look like watts written as candela ('" + generator +
           "' wrote a lamp's power as its intensity; --light-units radiometric reads them as "
           "W/sr, which leaves point and spot lights 4 pi too bright: add --exposure " +
           stops(-std::log2(4 * kPi)) + ")";
}

LightFacts light_facts(const SceneSetup& setup) {
    return {setup.default_lights, setup.file_lights, setup.scene.generator};
}

std::optional<ImageWarning> image_warning(const ImageExposure& e, const RenderCommandOptions& o,
                                          const LightFacts& facts) {
    if (!shows_light(o.integrator)) return std::nullopt;
    std::vector<std::string> causes;
    ImageWarning w;
    if (e.nearly_black()) {
        w.kind = "nearly black";
        w.message = "image nearly black: " + percent(e.lit_fraction) + " of its pixels reach " +
                    percent(kLitLuminance) + " of display white (under " +
                    percent(kMinLitFraction) + ")";
        if (!facts.default_lights && !user_environment(o))
            causes.push_back(o.default_light == DefaultLightMode::Off
                                 ? "the default lighting is off (--default-light auto or on "
                                   "adds a key and a fill light)"
                                 : "no default lighting (--default-light on adds a key and a "
                                   "fill light)");
        const std::string hint = light_units_hint(facts.generator, facts.file_lights, o.gltf.light_units);
        if (!hint.empty())
            causes.push_back(hint);
        else if (facts.file_lights > 0 && o.gltf.light_units == LightUnits::Photometric)
            causes.push_back(
                "light intensities in W/sr and W/m^2 rather than candela and lux "
                "(--light-units radiometric reads them 683 times brighter)");
        if (e.p99 > 0)
            causes.push_back("too little exposure (--exposure " +
                             stops(o.exposure + std::log2(kClipLuminance / e.p99)) +
                             " brings the brightest 1% of pixels to display white)");
        else
            causes.push_back(
                "almost no light reaches the camera (--env-color R G B or --env "
                "FILE lights the scene from around it)");
    } else if (e.mostly_clipped()) {
        w.kind = "mostly clipped";
        w.message = "image mostly clipped: " + percent(e.clipped_fraction) +
                    " of its pixels exceed display white (over " + percent(kMaxClippedFraction) +
                    ")";
        if (facts.file_lights > 0 && o.gltf.light_units == LightUnits::Radiometric)
            causes.push_back(
                "the file's intensities read as W/sr and W/m^2 (--light-units "
                "photometric, the spec's candela and lux, reads them 683 times "
                "dimmer)");
        if (facts.default_lights && o.default_light == DefaultLightMode::On)
            causes.push_back(
                "the default lights added to the scene's own (--default-light "
                "off leaves the scene to its own lights)");
        causes.push_back("too much exposure (--exposure " +
                         stops(o.exposure + std::log2(kMiddleGrey / std::max(e.median, 1e-30f))) +
                         " brings the median pixel to 18% grey)");
    } else {
        return std::nullopt;
    }
    w.message += "; likely causes: " + join(causes);
    return w;
}

}  // namespace penumbra
