// Everything `penumbra render` (and a job file's entry) can set, as typed values: each
// consumer's own settings struct sits here whole, so an option's field is named by its
// declaration (job/option_table.cpp) and its consumer, nowhere else.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/accel/accel.h"
#include "core/camera/orbit_cameras.h"
#include "core/film/filter.h"
#include "core/lights/default_lights.h"
#include "core/lights/light_set.h"
#include "core/sampling/sampler.h"
#include "integrators/integrator.h"
#include "io/color/color.h"
#include "io/gltf/gltf_loader.h"
#include "job/timeline.h"
#include "materials/material.h"

namespace penumbra {

// How the environment image's light samples are drawn. Auto: compensated where the
// integrator pairs every light sample with a BSDF sample by MIS, else full.
enum class EnvSamplingChoice { Auto, Full, Compensated };

// The environment light: an image or a constant colour (neither: none).
struct EnvironmentOptions {
    std::string image;        // equirectangular, +Y up
    std::vector<float> color;  // constant radiance r g b; empty: none
    float intensity = 1, rotation = 0;  // rotation about +Y in degrees
    EnvSamplingChoice sampling = EnvSamplingChoice::Auto;
};

// Depth of field overrides of the file's lens (0 / empty: the file's; aperture_radius -1
// keeps the file's, 0 is a pinhole; aperture_blades -1 keeps the file's).
struct LensOverrides {
    float fstop = 0, aperture_radius = -1, focus_distance = 0;
    int aperture_blades = -1;
    std::vector<float> focus_on;  // raster x y
};

struct RenderCommandOptions {
    // The batch: what to render and where the images go.
    std::vector<std::string> scenes;
    std::string output;   // -o: a file, or a name template when the batch has several images
    std::string out_dir = "out";
    // Name template in out_dir; empty: {scene}.exr, {scene}_{frame}.exr with frames,
    // {scene}/{view}.exr with views.
    std::string name;
    std::string job_file;  // JSON batch description
    std::string frames;    // "1-48", "3", "1,5,10-12"
    // "orbit:N" or a cameras JSON file (job/view_list.h): one image per view, all from
    // one load of the scene; empty: the file's camera.
    std::string views;
    OrbitSettings orbit;
    TimelineSettings timeline;  // a batch sets `frame` for each of `frames`
    double time_limit = 0;      // seconds per image; 0: none
    bool overwrite = false;     // re-render images whose complete output exists
    bool no_preview = false;
    bool quiet = false;
    double checkpoint_interval = 300;  // seconds; 0: only on an interrupt (job/checkpoint.h)
    int bands = 1;            // row bands per image on the farm
    int frames_per_task = 1;  // frames per farm task
    int threads = 0;          // 0: all cores

    // The image.
    int width = 0, height = 0;  // 0: derived from the camera's aspect ratio
    unsigned spp = 16;
    unsigned long long seed = 0;
    std::string camera;  // name or index; empty: the first camera, or a default one
    GltfLoadOptions gltf;  // variant, light units, strict, texture size limit
    bool no_file_lights = false;  // leave out the file's punctual lights
    DefaultLightMode default_light = DefaultLightMode::Auto;
    IntegratorType integrator = IntegratorType::Path;
    IntegratorOptions path;  // depth, strategy, light and BSDF samples, firefly control
    LightSetOptions lights;
    MaterialOptions materials;
    EnvironmentOptions env;
    LensOverrides lens;
    SamplerType sampler = SamplerType::TabledSobol;
    FilterType filter = FilterType::Gaussian;
    AccelType accel = AccelType::Embree;
    double target_error = 0;  // adaptive sampling; 0: off
    unsigned adaptive_min_spp = 0;
    bool denoise = false;  // the samples then form two independently seeded halves

    // The output: colour management, EXR layers and encoding.
    ColorSettings color;
    std::string aovs;  // --aov list; empty: none
    bool half = false;
    float exposure = 0;  // stops: the EXR and the preview are scaled by 2^exposure
    std::string compression = "zip";
    std::string reference;         // EXR to measure MSE and relMSE against
    bool timing_metadata = false;  // render time in the header (not reproducible)
};

}  // namespace penumbra
