#include "apps/penumbra/render_checkpoint.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace penumbra {

namespace {

std::string file_hash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    uint64_t h = 1469598103934665603ull;  // FNV-1a
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        for (std::streamsize i = 0; i < in.gcount(); ++i)
            h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
        if (!in) break;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

}  // namespace

std::string render_fingerprint(const BatchJob& job, const SceneSetup& setup,
                               const RenderOptions& ropt) {
    const RenderCommandOptions& o = job.options;
    std::ostringstream f;
    // max_digits10: a float option that differs in its last bit is another render.
    f.precision(17);
    f << "penumbra-checkpoint-v1 scene=" << job.scene << " bytes=" << file_hash(job.scene)
      << " size=" << setup.width << "x" << setup.height << " rows=" << ropt.row_begin << "-"
      << ropt.row_end << " spp=" << o.spp << " seed=" << o.seed << " sampler=" << o.sampler
      << " filter=" << o.filter << " integrator=" << o.integrator << " strategy=" << o.strategy
      << " microfacet=" << o.microfacet << " layering=" << o.gltf_layering
      << " light_samples=" << o.light_samples << " bsdf_samples=" << o.bsdf_samples
      << " max_depth=" << o.max_depth << " accel=" << o.accel << " camera=" << o.camera
      << " variant=" << o.variant << " env=" << o.env << " env_intensity=" << o.env_intensity
      << " env_rotation=" << o.env_rotation << " default_light=" << o.default_light
      << " light_units=" << o.light_units << " no_file_lights=" << o.no_file_lights
      << " fstop=" << o.fstop
      << " aperture_radius=" << o.aperture_radius << " focus_distance=" << o.focus_distance
      << " aperture_blades=" << o.aperture_blades << " shutter=" << setup.scene.shutter_open << "-"
      << setup.scene.shutter_close << " time=" << ropt.time << " aovs=" << o.aovs
      << " strict=" << o.strict << " max_texture_pixels=" << o.max_texture_pixels
      << " ocio=" << o.color.config << " working_space=" << o.color.working_space
      << " target_error=" << o.target_error << " adaptive_min_spp=" << o.adaptive_min_spp
      << " clamp_direct=" << o.clamp_direct << " clamp_indirect=" << o.clamp_indirect
      << " regularize=" << o.regularize << " light_sampler=" << o.light_sampler
      << " triangle_sampling=" << o.triangle_sampling << " env_sampling=" << o.env_sampling
      << " denoise=" << o.denoise;
    for (float c : o.env_color) f << " env_color=" << c;
    for (float c : o.focus_on) f << " focus_on=" << c;
    return f.str();
}

}  // namespace penumbra
