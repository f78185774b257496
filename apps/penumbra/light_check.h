// Whether an image is lit (core/film/image_exposure.h): the look at the view behind
// --default-light auto, a small preview rendered with the scene's own lights, and the
// warning after a render whose image is nearly black or mostly clipped, naming the
// likely cause and the option that changes it (docs/conventions.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "apps/penumbra/render_command.h"
#include "apps/penumbra/scene_setup.h"
#include "core/film/image_exposure.h"
#include "core/lights/light_set.h"

namespace penumbra {

// The preview: about kPreviewPixels pixels in the image's aspect ratio, kPreviewSpp
// samples each from a fixed seed, so the decision depends on the scene and the options
// alone, never on --seed, and the final image on (seed, pixel, sample index) alone.
constexpr int kPreviewPixels = 64 * 64;
constexpr unsigned kPreviewSpp = 4;

// Renders the preview of setup's view with its lights as they are and measures it at
// o.exposure.
ImageExposure preview_exposure(const SceneSetup& setup, const RenderCommandOptions& o);

// For --default-light auto when the scene's own lights were judged enough: renders the
// preview and, if it is nearly black, warns, adds the default lights and rebuilds
// setup.lights with light_options. Returns whether it added them.
bool add_default_lights_if_view_dark(SceneSetup& setup, const RenderCommandOptions& o,
                                     const LightSetOptions& light_options);

// A hint when the file's punctual light intensities look like watts written as candela:
// Khronos glTF Blender I/O 1.x (Blender 2.80 to 3.0) wrote a lamp's power in W as its
// intensity, whatever the light's type. Empty otherwise.
std::string light_units_hint(const std::string& generator, size_t file_lights,
                             LightUnits light_units);

struct ImageWarning {
    std::string kind;     // "nearly black" or "mostly clipped"
    std::string message;  // the measurement, then the likely causes and their options
};

// What the warning's causes read from the scene's setup. A render takes them from its
// SceneSetup; a farm merge, which loads no scene, from the bands' headers
// (penumbra:default_lights_added, penumbra:file_lights, penumbra:asset_generator).
struct LightFacts {
    bool default_lights = false;  // the default lights were added
    size_t file_lights = 0;       // the file's punctual lights rendered
    std::string generator;        // glTF asset.generator
};
LightFacts light_facts(const SceneSetup& setup);

// The warning for a finished image measured by `e`, or none when it is neither nearly
// black nor mostly clipped, or the integrator shows no light (a debug view).
std::optional<ImageWarning> image_warning(const ImageExposure& e, const RenderCommandOptions& o,
                                          const LightFacts& facts);

}  // namespace penumbra
