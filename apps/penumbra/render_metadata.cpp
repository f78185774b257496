#include "apps/penumbra/render_metadata.h"

#include "core/film/cryptomatte.h"
#include "job/aov_list.h"
#include "job/option_table.h"
#include "core/lights/environment_light.h"
#include "core/sampling/sampler.h"

namespace penumbra {

Metadata render_metadata(const RenderCommandOptions& o, const std::string& scene,
                         const SceneSetup& setup, const RenderStats& stats) {
    const CameraDesc& cam_desc = setup.camera_desc;
    // The options as given (job/option_table.cpp), then what they resolved to and what
    // the render did.
    Metadata metadata = option_metadata(o);
    const Metadata in_effect = {
        {"Software", std::string("penumbra ") + PENUMBRA_VERSION},
        {"penumbra:scene", scene},
        // What the environment's light samples followed (none without an environment).
        {"penumbra:env_sampling", environment_sampling_name(setup.lights->environment())},
        {"penumbra:default_lights_added", setup.default_lights ? "1" : "0"},
        {"penumbra:file_lights", std::to_string(setup.file_lights)},
        {"penumbra:asset_generator", setup.scene.generator},
        {"penumbra:sampler", sampler_name(sampler_in_effect(o.sampler, o.spp))},
        // The samples actually rendered: fewer than asked after a time limit or Ctrl-C.
        {"penumbra:spp", std::to_string(stats.spp)},
        {"penumbra:partial", stats.interrupted ? "1" : "0"},
        // The exposure in animation seconds; equal for a still (time is its opening).
        {"penumbra:time", std::to_string(setup.scene.shutter_open)},
        {"penumbra:shutter_open", std::to_string(setup.scene.shutter_open)},
        {"penumbra:shutter_close", std::to_string(setup.scene.shutter_close)},
        // The lens as rendered (file values with command-line overrides): 0 is a pinhole.
        {"penumbra:aperture_radius", cam_desc.aperture_radius},
        {"penumbra:focus_distance", cam_desc.focus_distance},
        {"penumbra:aperture_blades", cam_desc.aperture_blades},
        {"penumbra:rays", std::to_string(stats.rays)},
        {"penumbra:nonfinite_samples", std::to_string(stats.nonfinite_samples)},
    };
    metadata.insert(metadata.end(), in_effect.begin(), in_effect.end());
    if (!o.views.empty()) metadata.push_back({"penumbra:view", cam_desc.name});
    if (o.target_error > 0) {
        // What the adaptive render did: mean samples per pixel, pixels left unconverged.
        metadata.push_back(
            {"penumbra:mean_spp",
             std::to_string(double(stats.camera_samples) / (double(setup.width) * setup.height))});
        metadata.push_back({"penumbra:unconverged_pixels", std::to_string(stats.active_pixels)});
    }
    // Cryptomatte: each layer's name, hash, conversion and manifest (every name it can hold).
    const AovSet aovs = parse_aovs(o.aovs);
    if (aovs.has(Aov::CryptoObject))
        for (auto& [k, v] : cryptomatte_header(kCryptoObjectLayer,
                                               cryptomatte_object_names(setup.scene)))
            metadata.push_back({k, v});
    if (aovs.has(Aov::CryptoMaterial))
        for (auto& [k, v] : cryptomatte_header(kCryptoMaterialLayer,
                                               cryptomatte_material_names(setup.scene)))
            metadata.push_back({k, v});
    // Timing differs from run to run, so it is opt-in: by default the same command
    // writes a bitwise identical file (docs/conventions.md).
    if (o.timing_metadata) {
        metadata.push_back({"penumbra:render_seconds", float(stats.seconds)});
        metadata.push_back({"penumbra:load_seconds", float(setup.load_seconds)});
        metadata.push_back({"penumbra:build_seconds", float(setup.build_seconds)});
    }
    return metadata;
}

}  // namespace penumbra
