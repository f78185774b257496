#include "job/option_table.h"

#include <limits>
#include <stdexcept>

#include "job/aov_list.h"
#include "job/job_file.h"
#include "job/option_builders.h"
#include "job/option_table_parts.h"

namespace penumbra {

namespace {

using namespace option_builders;

const std::vector<Name<IntegratorType>> kIntegrators = {
    {"path", IntegratorType::Path},
    {"direct", IntegratorType::Direct},
    {"basic", IntegratorType::Basic},
    {"normal", IntegratorType::ShadingNormal},
    {"geometric-normal", IntegratorType::GeometricNormal},
    {"albedo", IntegratorType::Albedo},
    {"depth", IntegratorType::Depth},
    {"uv", IntegratorType::Uv},
    {"instance", IntegratorType::Instance}};

const std::vector<Name<SamplerType>> kSamplers = {
    {"independent", SamplerType::Independent},
    {"stratified", SamplerType::Stratified},
    {"sobol", SamplerType::Sobol},
    {"zsobol", SamplerType::ZSobol},
    {"tabled-sobol", SamplerType::TabledSobol}};

// What and where: the batch, its outputs and its bookkeeping (not pixels).
void add_batch_options(std::vector<OptionDecl>& t) {
    t.push_back(with_short(path({"output", "output", "", kNotPixels, kRender,
                                 "Output EXR; with several images, a name template as for "
                                 "--name; default: OUT_DIR/NAME"},
                                FIELD(output)),
                           "o"));
    t.push_back(path({"out-dir", "out_dir", "", kNotPixels, kRender,
                      "Folder for outputs when -o is not given"},
                     FIELD(out_dir)));
    t.push_back(text({"name", "name", "", kNotPixels, kRender,
                      "Output name template: {scene} (file stem), {camera} (name), {frame} (4 "
                      "digits), {view} (4 digits), {index} (position in the batch); default "
                      "{scene}.exr, {scene}_{frame}.exr with --frames, {scene}/{view}.exr "
                      "with --views"},
                     FIELD(name)));
    OptionDecl frames = timing(text({"frames", "frames", "", kNotPixels, kRender,
                                     "Render these frames (e.g. 1-48, 1-48:2, 1,5,10-12), one "
                                     "image each, the shutter opening at frame/fps (for "
                                     "--shutter of a frame)"},
                                    FIELD(frames)));
    frames.set = [](RenderCommandOptions& o, const std::string& list) {
        parse_frame_list(list);  // throws std::invalid_argument saying what is wrong
        o.frames = list;
    };
    t.push_back(frames);
    t.push_back(number<double>({"time-limit", "time_limit", "penumbra:time_limit", kNotPixels,
                                kRender,
                                "Seconds per image: render passes until the time is up or "
                                "--spp is reached; the EXR records the samples done",
                                Header::WhenPositive},
                               FIELD(time_limit), 0, kInf, true));
    t.push_back(flag({"overwrite", "", "", kNotPixels, kRender,
                      "Render images whose output exists (by default a finished output is "
                      "skipped, so an interrupted batch resumes)"},
                     FIELD(overwrite)));
    t.push_back(number<double>({"checkpoint-interval", "", "", kNotPixels, kRender,
                                "Seconds between checkpoints (OUTPUT.ckpt: the raw film, so "
                                "the same command continues a stopped render exactly); 0: "
                                "only on Ctrl-C or SIGTERM"},
                               FIELD(checkpoint_interval), 0, kInf));
    t.push_back(flag({"no-preview", "", "", kNotPixels, kRender,
                      "Do not write the sRGB PNG preview"},
                     FIELD(no_preview)));
    t.push_back(number<int>({"bands", "bands", "", kNotPixels, kFarm,
                             "penumbra farm: row bands per image, one farm task each"},
                            FIELD(bands), 1, 1 << 15));
    t.push_back(number<int>({"frames-per-task", "frames_per_task", "", kNotPixels, kFarm,
                             "penumbra farm: consecutive frames of an entry rendered by one "
                             "task"},
                            FIELD(frames_per_task), 1, 1 << 20));
}

// How light is transported: integrator, sampler, filter, accelerator and their settings.
void add_method_options(std::vector<OptionDecl>& t) {
    t.push_back(choice<IntegratorType>(
        {"integrator", "integrator", "penumbra:integrator", kPixels, kImage,
         "Integrator: path (path tracing with next-event estimation and MIS), direct "
         "(direct light only: many light and BSDF samples, specular recursion), basic "
         "(classic ray tracer: punctual lights, mirror recursion); debug views of the first "
         "hit: normal and geometric-normal (0.5 n + 0.5), albedo (base colour), depth, uv "
         "(TEXCOORD_0), instance (a colour per instance)",
         Header::Always},
        FIELD(integrator), kIntegrators));
    t.push_back(choice<SamplerType>({"sampler", "sampler", "", kPixels, kImage, "Pixel sampler"},
                                    FIELD(sampler), kSamplers));
    t.push_back(choice<FilterType>({"filter", "filter", "penumbra:filter", kPixels, kImage,
                                    "Pixel reconstruction filter", Header::Always},
                                   FIELD(filter),
                                   {{"box", FilterType::Box},
                                    {"gaussian", FilterType::Gaussian},
                                    {"blackman-harris", FilterType::BlackmanHarris}}));
    // Every accelerator gives the same hits; the choice is for speed and cross-checks, but
    // an image could still differ in a tie between coincident faces.
    t.push_back(choice<AccelType>({"accel", "accel", "penumbra:accelerator", kPixels, kImage,
                                   "Ray intersection accelerator (bvh: bvh-sah)", Header::Always},
                                  FIELD(accel),
                                  {{"embree", AccelType::Embree},
                                   {"bvh-sah", AccelType::BvhSah},
                                   {"bvh", AccelType::BvhSah},
                                   {"bvh-median", AccelType::BvhMedian},
                                   {"bvh-center", AccelType::BvhCenter},
                                   {"grid", AccelType::Grid}}));
    t.push_back(choice<LightStrategy>(
        {"strategy", "strategy", "penumbra:strategy", kPixels, kImage,
         "path: estimators for area and environment light: mis (both, combined), bsdf (BSDF "
         "sampling only) or light (light sampling only)",
         Header::Always},
        FIELD(path.strategy),
        {{"mis", LightStrategy::Mis}, {"bsdf", LightStrategy::BsdfOnly},
         {"light", LightStrategy::LightOnly}}));
    t.push_back(choice<LightSamplerType>(
        {"light-sampler", "light_sampler", "penumbra:light_sampler", kPixels, kImage,
         "How next-event estimation chooses a light: uniform, power (by emitted power), bvh "
         "(a light BVH weighing distance, orientation and power) or auto (bvh from 64 "
         "emitters and punctual lights on, else power)",
         Header::Always},
        FIELD(lights.sampler),
        {{"uniform", LightSamplerType::Uniform}, {"power", LightSamplerType::Power},
         {"bvh", LightSamplerType::Bvh}, {"auto", LightSamplerType::Auto}}));
    t.push_back(choice<TriangleSampling>(
        {"triangle-sampling", "triangle_sampling", "penumbra:triangle_sampling", kPixels, kImage,
         "Points on emissive triangles: solid-angle (spherical triangles, cosine warped) or "
         "area (uniform by area)",
         Header::Always},
        FIELD(lights.triangles),
        {{"area", TriangleSampling::Area}, {"solid-angle", TriangleSampling::SolidAngle}}));
    t.push_back(choice<MicrofacetType>(
        {"microfacet", "microfacet", "penumbra:microfacet", kPixels, kImage,
         "Microfacet distribution of glTF materials: ggx (the spec's) or beckmann",
         Header::Always},
        FIELD(materials.gltf_distribution),
        {{"ggx", MicrofacetType::Ggx}, {"beckmann", MicrofacetType::Beckmann}}));
    t.push_back(choice<GltfLayering>(
        {"gltf-layering", "gltf_layering", "penumbra:gltf_layering", kPixels, kImage,
         "Diffuse base of glTF dielectrics: albedo-scaled (energy-conserving) or spec "
         "(Appendix B's fresnel_mix as written; gains energy at grazing angles)",
         Header::Always},
        FIELD(materials.gltf_layering),
        {{"albedo-scaled", GltfLayering::AlbedoScaled}, {"spec", GltfLayering::Spec}}));
    t.push_back(number<int>({"light-samples", "light_samples", "", kPixels, kImage,
                             "direct: shadow rays per shading point"},
                            FIELD(path.light_samples), 0, 1 << 16));
    t.push_back(number<int>({"bsdf-samples", "bsdf_samples", "", kPixels, kImage,
                             "direct: BSDF samples per shading point"},
                            FIELD(path.bsdf_samples), 0, 1 << 16));
    t.push_back(number<int>({"max-depth", "max_depth", "penumbra:max_depth", kPixels, kImage,
                             "path: maximum bounces; basic/direct: maximum specular recursion",
                             Header::Always},
                            FIELD(path.max_depth), 0, 1024));
}

// The environment light: an image or a constant colour.
void add_environment_options(std::vector<OptionDecl>& t) {
    t.push_back(path({"env", "env", "", kPixels, kImage,
                      "Environment: an equirectangular HDR/EXR image (+Y up), importance-sampled"},
                     FIELD(env.image), true));
    t.push_back(numbers({"env-color", "env_color", "", kPixels, kImage,
                         "Environment: constant radiance R G B"},
                        FIELD(env.color), 3));
    t.push_back(number<float>({"env-intensity", "env_intensity", "", kPixels, kImage,
                               "Scale of the environment radiance"},
                              FIELD(env.intensity), 0, kInf));
    t.push_back(number<float>({"env-rotation", "env_rotation", "", kPixels, kImage,
                               "Rotation of the environment image about +Y, in degrees"},
                              FIELD(env.rotation), -kInf, kInf));
    t.push_back(choice<EnvSamplingChoice>(
        {"env-sampling", "env_sampling", "", kPixels, kImage,
         "Environment image's light samples: full (by luminance), compensated (luminance "
         "above the map's mean: the BSDF samples MIS pairs them with find the rest; needs "
         "such pairs) or auto (compensated where the integrator pairs them)"},
        FIELD(env.sampling),
        {{"auto", EnvSamplingChoice::Auto}, {"full", EnvSamplingChoice::Full},
         {"compensated", EnvSamplingChoice::Compensated}}));
}

// Depth of field, overriding the file's lens (the header records the lens as rendered).
void add_lens_options(std::vector<OptionDecl>& t) {
    t.push_back(number<float>({"aperture-radius", "aperture_radius", "", kPixels, kImage,
                               "Depth of field: lens aperture radius in scene units (0: "
                               "pinhole, whatever the file says; -1: the file's)"},
                              FIELD(lens.aperture_radius), -1, kInf));
    t.push_back(number<float>({"fstop", "fstop", "", kPixels, kImage,
                               "Depth of field: f-number (aperture from the focal length of "
                               "the camera's field of view and its sensor, 24 mm high unless "
                               "the file says otherwise; 0: the file's or --aperture-radius)"},
                              FIELD(lens.fstop), 0, kInf));
    t.push_back(number<float>({"focus-distance", "focus_distance", "", kPixels, kImage,
                               "Depth of field: distance of the plane of focus along the view "
                               "axis (0: the file's)"},
                              FIELD(lens.focus_distance), 0, kInf));
    t.push_back(numbers({"focus-on", "focus_on", "", kPixels, kImage,
                         "Depth of field: focus on the surface seen through pixel X Y"},
                        FIELD(lens.focus_on), 2));
    t.push_back(number<int>({"aperture-blades", "aperture_blades", "", kPixels, kImage,
                             "Depth of field: aperture blades (0: circular, >= 3: polygonal "
                             "bokeh; -1: the file's)"},
                            FIELD(lens.aperture_blades), -1, 64));
}

// Which lights the file contributes, and how strictly it is read.
void add_scene_light_options(std::vector<OptionDecl>& t) {
    t.push_back(choice<DefaultLightMode>(
        {"default-light", "default_light", "penumbra:default_light", kPixels, kImage,
         "Default key and fill lights and a dim environment: auto (when the scene has no "
         "lights, no environment and no emitters bright and large enough to light it), on "
         "(always), off (never)",
         Header::Always},
        FIELD(default_light),
        {{"auto", DefaultLightMode::Auto}, {"on", DefaultLightMode::On},
         {"off", DefaultLightMode::Off}}));
    // A spelling of --default-light off: the fingerprint and header see that option.
    OptionDecl no_default = declare({"no-default-light", "", "", kPixels, kImage,
                                     "Same as --default-light off"},
                                    OptionKind::Flag);
    no_default.get = [](const RenderCommandOptions& o) {
        return std::string(o.default_light == DefaultLightMode::Off ? "1" : "0");
    };
    no_default.set = [](RenderCommandOptions& o, const std::string& v) {
        if (v == "1") o.default_light = DefaultLightMode::Off;
    };
    no_default.header = [](const RenderCommandOptions&) { return std::nullopt; };
    t.push_back(no_default);
    t.push_back(flag({"no-file-lights", "no_file_lights", "penumbra:no_file_lights", kPixels,
                      kImage,
                      "Leave out the file's punctual lights (KHR_lights_punctual), so that "
                      "--env or --env-color can be the only light; emissive surfaces still emit",
                      Header::Always},
                     FIELD(no_file_lights)));
    t.push_back(choice<LightUnits>(
        {"light-units", "light_units", "penumbra:light_units", kPixels, kImage,
         "KHR_lights_punctual intensities: photometric (candela and lux, as the spec says, "
         "converted at 683 lm/W) or radiometric (read as W/sr and W/m^2)",
         Header::Always},
        FIELD(gltf.light_units),
        {{"photometric", LightUnits::Photometric}, {"radiometric", LightUnits::Radiometric}}));
    t.push_back(flag({"strict", "strict", "", kPixels, kImage,
                      "Treat every scene warning (an undecodable texture, out-of-spec data, an "
                      "ignored extension) as an error"},
                     FIELD(gltf.strict)));
    t.push_back(number<uint64_t>({"max-texture-pixels", "max_texture_pixels", "", kPixels, kImage,
                                  "Refuse (as undecodable) texture images whose header claims "
                                  "more pixels"},
                                 FIELD(gltf.max_texture_pixels), 1, double(uint64_t(1) << 40)));
}

// Adaptive sampling, firefly control and denoising.
void add_sampling_options(std::vector<OptionDecl>& t) {
    t.push_back(number<double>({"target-error", "target_error", "penumbra:target_error", kPixels,
                                kImage,
                                "Adaptive sampling: stop each pixel once its estimated relative "
                                "standard error (from two independent halves of its samples) is "
                                "below this, e.g. 0.02; --spp is then the most a pixel takes. "
                                "Adds the Error and Samples layers",
                                Header::WhenPositive},
                               FIELD(target_error), 0, kInf, true));
    OptionDecl min_spp = number<unsigned>(
        {"adaptive-min-spp", "adaptive_min_spp", "penumbra:adaptive_min_spp", kPixels, kImage,
         "Adaptive sampling: samples every pixel takes first (0: 16 / E^0.3, at least 8, as "
         "Cycles' automatic minimum)",
         Header::WithAdaptive},
        FIELD(adaptive_min_spp), 0, 1u << 24);
    min_spp.header = [](const RenderCommandOptions& o) -> std::optional<MetadataValue> {
        if (!(o.target_error > 0)) return std::nullopt;
        return MetadataValue(std::to_string(o.adaptive_min_spp));
    };
    t.push_back(min_spp);
    t.push_back(number<float>({"clamp-direct", "clamp_direct", "penumbra:clamp_direct", kPixels,
                               kImage,
                               "path: clamp each contribution of direct light (at most one "
                               "bounce) to this largest component, as Cycles' Clamp Direct (0: "
                               "off; biased)",
                               Header::WhenPositive},
                              FIELD(path.clamp_direct), 0, kInf));
    t.push_back(number<float>({"clamp-indirect", "clamp_indirect", "penumbra:clamp_indirect",
                               kPixels, kImage,
                               "path: clamp each contribution of indirect light (two or more "
                               "bounces) to this largest component, as Cycles' Clamp Indirect "
                               "(0: off; biased)",
                               Header::WhenPositive},
                              FIELD(path.clamp_indirect), 0, kInf));
    t.push_back(number<float>({"regularize", "regularize", "penumbra:regularize", kPixels, kImage,
                               "path: after the first non-specular bounce, shade glTF materials "
                               "with at least this roughness (Cycles' Filter Glossy; 0: off; "
                               "biased)",
                               Header::WhenPositive},
                              FIELD(path.regularize_roughness), 0, 1));
    t.push_back(flag({"transparent-background", "transparent_background",
                      "penumbra:transparent_background", kPixels, kRender,
                      "Camera rays that miss all geometry give zero colour and zero alpha: alpha "
                      "is the camera rays' coverage, filtered as the colour and premultiplied "
                      "(the environment and default lights still light the scene and are seen "
                      "in reflections and through glass, which covers)",
                      Header::Always},
                     FIELD(path.transparent_background)));
    t.push_back(flag({"denoise", "denoise", "", kPixels, kImage,
                      "Denoise the EXR's RGB (and the preview) after rendering, feature-guided "
                      "(NFOR); the unbiased estimate is kept as the layer Noisy.R/G/B and the "
                      "header gets the denoiser's estimated relMSE. Like the error layer, it "
                      "draws the samples as two independently seeded halves"},
                     FIELD(denoise)));
}

// Colour management and the EXR's layers and encoding.
void add_output_options(std::vector<OptionDecl>& t) {
    OptionDecl ocio = path({"ocio-config", "ocio_config", "", kPixels, kRender,
                            "OpenColorIO config file (default: $OCIO, else the built-in config; "
                            "'builtin' forces the built-in one)"},
                           FIELD(color.config), true);
    ocio.choices = {"builtin"};
    t.push_back(ocio);
    t.push_back(text({"working-space", "working_space", "", kPixels, kRender,
                      "Rendering colour space, linear (default: the config's scene_linear role; "
                      "built-in: 'Linear Rec.709 (sRGB)', or ACEScg). glTF colours are converted "
                      "into it at load"},
                     FIELD(color.working_space)));
    t.push_back(text({"output-colorspace", "output_colorspace", "", kPixels, kRender,
                      "Colour space of the EXR (default: the working space); the header gets "
                      "its name and chromaticities"},
                     FIELD(color.output_space)));
    t.push_back(text({"display", "display", "", kNotPixels, kRender,
                      "OCIO display for the preview (default: the config's, built-in: sRGB)"},
                     FIELD(color.display)));
    t.push_back(text({"view", "view", "", kNotPixels, kRender,
                      "OCIO view for the preview (default: the display's; built-in: Standard, "
                      "'ACES 1.0 - SDR Video', Raw)"},
                     FIELD(color.view)));
    t.push_back(text({"look", "look", "", kNotPixels, kRender, "OCIO look(s) applied to the preview"},
                     FIELD(color.look)));
    OptionDecl aov = text({"aov", "aov", "", kPixels, kRender,
                           "Extra EXR layers, comma-separated: albedo, normal, depth, position, "
                           "variance, samples, object_id, material_id (glTF node and material "
                           "index of the sample nearest each pixel's centre; -1: no hit, -2: "
                           "the default material), vector (motion vectors in pixels to the "
                           "previous and from the next frame, 1 / fps away, as Cycles' Vector "
                           "pass) (or all), error (relative standard error "
                           "from two independently seeded halves of the samples; it changes the "
                           "noise, so 'all' leaves it out), and crypto_object, crypto_material "
                           "or cryptomatte for both (Cryptomatte layers of the glTF node and "
                           "material names, with the manifest in the header; not in 'all')"},
                          FIELD(aovs));
    aov.set = [](RenderCommandOptions& o, const std::string& list) {
        parse_aovs(list);  // throws std::invalid_argument naming an unknown layer
        o.aovs = list;
    };
    t.push_back(aov);
    t.push_back(flag({"half", "half", "", kPixels, kRender,
                      "16-bit float EXR colour channels (depth, position, samples stay 32-bit)"},
                     FIELD(half)));
    OptionDecl compression = text({"compression", "compression", "", kNotPixels, kRender,
                                   "EXR compression (pxr24, b44*, dwa* lossy)"},
                                  FIELD(compression));
    compression.kind = OptionKind::Choice;
    compression.choices = exr_compressions();
    compression.set = [](RenderCommandOptions& o, const std::string& name) {
        for (const std::string& c : exr_compressions())
            if (c == name) {
                o.compression = name;
                return;
            }
        throw std::invalid_argument("unknown EXR compression '" + name + "'");
    };
    t.push_back(compression);
    t.push_back(number<float>({"exposure", "exposure", "penumbra:exposure", kPixels, kRender,
                               "Exposure in stops: the EXR and the preview are scaled by 2^EV "
                               "(recorded in the header as penumbra:exposure)",
                               Header::AsFloat},
                              FIELD(exposure), -64, 64));
    t.push_back(path({"reference", "", "", kNotPixels, kRender,
                      "Reference EXR (same size, output colour space): MSE and relMSE go into "
                      "the header and the summary"},
                     FIELD(reference), true));
    t.push_back(flag({"timing-metadata", "", "", kNotPixels, kRender,
                      "Record the render time in the EXR header (then files differ from run to "
                      "run; without it the same command gives a bitwise identical file)"},
                     FIELD(timing_metadata)));
    t.push_back(with_short(flag({"quiet", "", "", kNotPixels, kImage, "Only print errors"},
                                FIELD(quiet)),
                           "q"));
}

std::vector<OptionDecl> make_table() {
    std::vector<OptionDecl> t;
    add_batch_options(t);
    add_view_options(t);
    add_timeline_options(t);
    add_frame_options(t);
    add_method_options(t);
    add_environment_options(t);
    add_lens_options(t);
    add_scene_light_options(t);
    add_sampling_options(t);
    add_output_options(t);
    return t;
}

}  // namespace

const std::vector<OptionDecl>& render_option_table() {
    static const std::vector<OptionDecl> table = make_table();
    return table;
}

std::string sampler_name(SamplerType type) {
    for (const Name<SamplerType>& n : kSamplers)
        if (n.value == type) return n.name;
    throw std::logic_error("a sampler without a name");
}

}  // namespace penumbra
