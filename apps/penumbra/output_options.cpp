#include "apps/penumbra/output_options.h"

#include <stdexcept>

#include "core/film/aov.h"
#include "io/image/image_writer.h"

namespace penumbra {

void add_output_options(CLI::App* cmd, RenderCommandOptions& o) {
    cmd->add_option("--ocio-config", o.color.config,
                    "OpenColorIO config file (default: $OCIO, else the built-in config; "
                    "'builtin' forces the built-in one)")
        ->check(CLI::ExistingFile | CLI::IsMember({"builtin"}));
    cmd->add_option("--working-space", o.color.working_space,
                    "Rendering colour space, linear (default: the config's scene_linear role; "
                    "built-in: 'Linear Rec.709 (sRGB)', or ACEScg). glTF colours are converted "
                    "into it at load");
    cmd->add_option("--output-colorspace", o.color.output_space,
                    "Colour space of the EXR (default: the working space); the header gets "
                    "its name and chromaticities");
    cmd->add_option("--display", o.color.display,
                    "OCIO display for the preview (default: the config's, built-in: sRGB)");
    cmd->add_option("--view", o.color.view,
                    "OCIO view for the preview (default: the display's; built-in: Standard, "
                    "'ACES 1.0 - SDR Video', Raw)");
    cmd->add_option("--look", o.color.look, "OCIO look(s) applied to the preview");
    cmd->add_option("--aov", o.aovs,
                    "Extra EXR layers, comma-separated: albedo, normal, depth, position, "
                    "variance, samples (or all), and error (relative standard error from two "
                    "independently seeded halves of the samples; it changes the noise, so "
                    "'all' leaves it out)")
        ->check([](const std::string& list) {
            try {
                parse_aovs(list);
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
            return std::string();
        });
    cmd->add_flag("--half", o.half,
                  "16-bit float EXR colour channels (depth, position, samples stay 32-bit)");
    cmd->add_option("--compression", o.compression, "EXR compression (pxr24, b44*, dwa* lossy)")
        ->capture_default_str()
        ->check(CLI::IsMember(exr_compressions()));
    cmd->add_option("--exposure", o.exposure,
                    "Exposure in stops: the EXR and the preview are scaled by 2^EV (recorded "
                    "in the header as penumbra:exposure)")
        ->capture_default_str()
        ->check(CLI::Range(-64.0f, 64.0f));
    cmd->add_option("--reference", o.reference,
                    "Reference EXR (same size, output colour space): MSE and relMSE go into "
                    "the header and the summary")
        ->check(CLI::ExistingFile);
    cmd->add_flag("--timing-metadata", o.timing_metadata,
                  "Record the render time in the EXR header (then files differ from run to "
                  "run; without it the same command gives a bitwise identical file)");
}

}  // namespace penumbra
