#include "apps/penumbra/sampling_options.h"

#include <string>

namespace penumbra {

void add_sampling_options(CLI::App* cmd, RenderCommandOptions& o) {
    cmd->add_option("--target-error", o.target_error,
                    "Adaptive sampling: stop each pixel once its estimated relative standard "
                    "error (from two independent halves of its samples) is below this, e.g. "
                    "0.02; --spp is then the most a pixel takes. Adds the Error and Samples "
                    "layers")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--adaptive-min-spp", o.adaptive_min_spp,
                    "Adaptive sampling: samples every pixel takes first (0: 16 / E^0.3, at "
                    "least 8, as Cycles' automatic minimum)")
        ->capture_default_str()
        ->check(CLI::Range(0u, 1u << 24));
    cmd->add_option("--clamp-direct", o.clamp_direct,
                    "path: clamp each contribution of direct light (at most one bounce) to "
                    "this largest component, as Cycles' Clamp Direct (0: off; biased)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--clamp-indirect", o.clamp_indirect,
                    "path: clamp each contribution of indirect light (two or more bounces) to "
                    "this largest component, as Cycles' Clamp Indirect (0: off; biased)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--regularize", o.regularize,
                    "path: after the first non-specular bounce, shade glTF materials with at "
                    "least this roughness (Cycles' Filter Glossy; 0: off; biased)")
        ->capture_default_str()
        ->check(CLI::Range(0.0f, 1.0f));
    cmd->add_flag("--denoise", o.denoise,
                  "Denoise the EXR's RGB (and the preview) after rendering, feature-guided "
                  "(NFOR); the unbiased estimate is kept as the layer Noisy.R/G/B and the "
                  "header gets the denoiser's estimated relMSE. Like the error layer, it "
                  "draws the samples as two independently seeded halves");
}

Metadata sampling_metadata(const RenderCommandOptions& o) {
    Metadata m;
    if (o.target_error > 0) {
        m.push_back({"penumbra:target_error", std::to_string(o.target_error)});
        m.push_back({"penumbra:adaptive_min_spp", std::to_string(o.adaptive_min_spp)});
    }
    if (o.clamp_direct > 0) m.push_back({"penumbra:clamp_direct", std::to_string(o.clamp_direct)});
    if (o.clamp_indirect > 0)
        m.push_back({"penumbra:clamp_indirect", std::to_string(o.clamp_indirect)});
    if (o.regularize > 0) m.push_back({"penumbra:regularize", std::to_string(o.regularize)});
    return m;
}

}  // namespace penumbra
