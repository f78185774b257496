#include "apps/penumbra/render_metadata.h"

#include "apps/penumbra/sampling_options.h"
#include "core/lights/environment_light.h"
#include "core/sampling/sampler.h"

namespace penumbra {

Metadata render_metadata(const RenderCommandOptions& o, const std::string& scene,
                         const SceneSetup& setup, const RenderStats& stats) {
    const CameraDesc& cam_desc = setup.camera_desc;
    Metadata metadata = {
        {"Software", std::string("penumbra ") + PENUMBRA_VERSION},
        {"penumbra:scene", scene},
        {"penumbra:integrator", o.integrator},
        {"penumbra:strategy", o.strategy},
        {"penumbra:light_sampler", o.light_sampler},
        {"penumbra:triangle_sampling", o.triangle_sampling},
        // What the environment's light samples followed (none without an environment).
        {"penumbra:env_sampling", environment_sampling_name(setup.lights->environment())},
        {"penumbra:microfacet", o.microfacet},
        {"penumbra:gltf_layering", o.gltf_layering},
        {"penumbra:max_depth", std::to_string(o.max_depth)},
        // How the image's light was set up: glTF light units, default lights, exposure.
        {"penumbra:light_units", o.light_units},
        {"penumbra:default_light", o.default_light},
        {"penumbra:default_lights_added", setup.default_lights ? "1" : "0"},
        {"penumbra:no_file_lights", o.no_file_lights ? "1" : "0"},
        {"penumbra:file_lights", std::to_string(setup.file_lights)},
        {"penumbra:asset_generator", setup.scene.generator},
        {"penumbra:exposure", o.exposure},
        {"penumbra:accelerator", o.accel},
        {"penumbra:sampler", sampler_in_effect(parse_sampler_type(o.sampler), o.spp)},
        {"penumbra:filter", o.filter},
        // The samples actually rendered: fewer than asked after a time limit or Ctrl-C.
        {"penumbra:spp", std::to_string(stats.spp)},
        {"penumbra:spp_requested", std::to_string(o.spp)},
        {"penumbra:partial", stats.interrupted ? "1" : "0"},
        {"penumbra:seed", std::to_string(o.seed)},
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
    if (o.timeline.frame) metadata.push_back({"penumbra:frame", std::to_string(*o.timeline.frame)});
    if (o.time_limit > 0) metadata.push_back({"penumbra:time_limit", std::to_string(o.time_limit)});
    for (auto& field : sampling_metadata(o)) metadata.push_back(std::move(field));
    if (o.target_error > 0) {
        // What the adaptive render did: mean samples per pixel, pixels left unconverged.
        metadata.push_back(
            {"penumbra:mean_spp",
             std::to_string(double(stats.camera_samples) / (double(setup.width) * setup.height))});
        metadata.push_back({"penumbra:unconverged_pixels", std::to_string(stats.active_pixels)});
    }
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
