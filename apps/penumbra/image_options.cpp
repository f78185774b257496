#include "apps/penumbra/image_options.h"

#include <string>
#include <vector>

#include "apps/penumbra/sampling_options.h"
#include "integrators/integrator.h"

namespace penumbra {

namespace {

// Image size, samples, threads, seed and what of the file to render.
void add_frame_options(CLI::App* cmd, RenderCommandOptions& o) {
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
    cmd->add_option("--variant", o.variant,
                    "glTF material variant by name (KHR_materials_variants; default: the "
                    "default materials)");
}

// How light is transported: integrator, sampler, filter, accelerator and their settings.
void add_method_options(CLI::App* cmd, RenderCommandOptions& o) {
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
        ->check(CLI::IsMember({"independent", "stratified", "sobol", "zsobol", "tabled-sobol"}));
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
    cmd->add_option("--light-sampler", o.light_sampler,
                    "How next-event estimation chooses a light: uniform, power (by emitted "
                    "power), bvh (a light BVH weighing distance, orientation and power) or "
                    "auto (bvh from 64 emitters and punctual lights on, else power)")
        ->capture_default_str()
        ->check(CLI::IsMember({"uniform", "power", "bvh", "auto"}));
    cmd->add_option("--triangle-sampling", o.triangle_sampling,
                    "Points on emissive triangles: solid-angle (spherical triangles, cosine "
                    "warped) or area (uniform by area)")
        ->capture_default_str()
        ->check(CLI::IsMember({"area", "solid-angle"}));
    cmd->add_option("--microfacet", o.microfacet,
                    "Microfacet distribution of glTF materials: ggx (the spec's) or beckmann")
        ->capture_default_str()
        ->check(CLI::IsMember({"ggx", "beckmann"}));
    cmd->add_option("--gltf-layering", o.gltf_layering,
                    "Diffuse base of glTF dielectrics: albedo-scaled (energy-conserving) or "
                    "spec (Appendix B's fresnel_mix as written; gains energy at grazing angles)")
        ->capture_default_str()
        ->check(CLI::IsMember({"albedo-scaled", "spec"}));
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
}

// The environment light: an image or a constant colour.
void add_environment_options(CLI::App* cmd, RenderCommandOptions& o) {
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
    cmd->add_option("--env-sampling", o.env_sampling,
                    "Environment image's light samples: full (by luminance), compensated "
                    "(luminance above the map's mean: the BSDF samples MIS pairs them with "
                    "find the rest; needs such pairs) or auto (compensated where the "
                    "integrator pairs them)")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "full", "compensated"}));
}

// Depth of field, overriding the file's lens.
void add_lens_options(CLI::App* cmd, RenderCommandOptions& o) {
    auto* aperture = cmd->add_option("--aperture-radius", o.aperture_radius,
                                     "Depth of field: lens aperture radius in scene units "
                                     "(0: pinhole, whatever the file says)")
                         ->check(CLI::NonNegativeNumber);
    cmd->add_option("--fstop", o.fstop,
                    "Depth of field: f-number (aperture from the focal length of the camera's "
                    "field of view and its sensor, 24 mm high unless the file says otherwise)")
        ->check(CLI::PositiveNumber)
        ->excludes(aperture);
    cmd->add_option("--focus-distance", o.focus_distance,
                    "Depth of field: distance of the plane of focus along the view axis")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--focus-on", o.focus_on,
                    "Depth of field: focus on the surface seen through pixel X Y")
        ->expected(2);
    cmd->add_option("--aperture-blades", o.aperture_blades,
                    "Depth of field: aperture blades (0: circular, >= 3: polygonal bokeh)")
        ->check(CLI::Range(0, 64));
}

// Which lights the file contributes, and how strictly it is read.
void add_scene_light_options(CLI::App* cmd, RenderCommandOptions& o) {
    cmd->add_option("--default-light", o.default_light,
                    "Default key and fill lights and a dim environment: auto (when the scene "
                    "has no lights, no environment and no emitters bright and large enough to "
                    "light it), on (always), off (never)")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "on", "off"}));
    cmd->add_flag_callback(
        "--no-default-light", [&o] { o.default_light = "off"; }, "Same as --default-light off");
    cmd->add_flag("--no-file-lights", o.no_file_lights,
                  "Leave out the file's punctual lights (KHR_lights_punctual), so that --env or "
                  "--env-color can be the only light; emissive surfaces still emit");
    cmd->add_option("--light-units", o.light_units,
                    "KHR_lights_punctual intensities: photometric (candela and lux, as the "
                    "spec says, converted at 683 lm/W) or radiometric (read as W/sr and W/m^2)")
        ->capture_default_str()
        ->check(CLI::IsMember({"photometric", "radiometric"}));
    cmd->add_flag("--strict", o.strict,
                  "Treat every scene warning (an undecodable texture, out-of-spec data, an "
                  "ignored extension) as an error");
    cmd->add_option("--max-texture-pixels", o.max_texture_pixels,
                    "Refuse (as undecodable) texture images whose header claims more pixels")
        ->capture_default_str()
        ->check(CLI::Range(uint64_t(1), uint64_t(1) << 40));
}

}  // namespace

void add_image_options(CLI::App* cmd, RenderCommandOptions& o) {
    add_frame_options(cmd, o);
    add_method_options(cmd, o);
    add_environment_options(cmd, o);
    add_lens_options(cmd, o);
    add_scene_light_options(cmd, o);
    add_sampling_options(cmd, o);
}

}  // namespace penumbra
