// Colour management with OpenColorIO 2.1, the only place that uses it: the working
// (rendering) space glTF colours are converted into, the output space of the EXR and
// the display/view/look of 8-bit previews, from a studio config or a built-in one.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/image.h"
#include "core/math/mat3.h"
#include "io/color/color_primaries.h"

namespace penumbra {

// What the user chose; empty strings take the defaults.
struct ColorSettings {
    std::string config;         // --ocio-config FILE; empty: $OCIO, else the built-in config
    std::string working_space;  // empty: the config's scene_linear role
    std::string output_space;   // empty: the working space
    std::string display;        // empty: the config's default display
    std::string view;           // empty: the display's default view
    std::string look;           // empty: none beyond the view's own
};

// The colour pipeline of one run: immutable after construction and safe to share between
// threads. Colour space names may be names, aliases or roles of the config; accessors
// return the config's canonical names.
class ColorPipeline {
public:
    // Throws SceneError naming the config and the unknown or unsuitable name (with the
    // names available) when the config cannot be loaded or a choice does not fit it.
    explicit ColorPipeline(const ColorSettings& settings = {});
    ~ColorPipeline();
    ColorPipeline(ColorPipeline&&) noexcept;
    ColorPipeline& operator=(ColorPipeline&&) noexcept;

    // The built-in config with default choices, ignoring $OCIO: linear Rec.709 working
    // and output space, the sRGB display's Standard view (the plain sRGB curve).
    static const ColorPipeline& builtin();

    const std::string& config_source() const;  // the file, or "built-in"
    const std::string& working_space() const;
    const std::string& output_space() const;
    const std::string& display() const;
    const std::string& view() const;
    const std::string& look() const;

    // glTF colours (linear Rec.709, D65) to the working space. Exactly the identity
    // when the working space has Rec.709 primaries (recognised as known_primaries are),
    // so renders in any config's Rec.709 space match bit for bit.
    const Mat3& rec709_to_working() const;
    bool working_is_rec709() const;

    // Working space to output space, in place, on the colour channels (RGB of RGB or
    // RGBA; alpha untouched). No-op when they are the same space.
    void to_output(Image& image) const;
    // Display-encoded RGB in [0,1] for an 8-bit preview: the image (working space)
    // scaled by 2^exposure, through display/view/look, clamped; NaN becomes 0.
    Image to_display(const Image& working, float exposure = 0) const;

    // The output space's primaries and white, for the EXR header. Empty when the space
    // is not linear or the config cannot relate it to CIE XYZ (no interchange role).
    const std::optional<Chromaticities>& output_chromaticities() const;

    // Linear RGB in `space` to CIE XYZ under D65 as a matrix, through the config's
    // aces_interchange (or cie_xyz_d65_interchange) role. Empty when the config has
    // neither role or the conversion is not linear (a log or display encoding).
    std::optional<Mat3> to_xyz_d65(const std::string& space) const;
    // Converts count RGB triples between two spaces of the config, in place.
    void convert(float* rgb, size_t count, const std::string& from, const std::string& to) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

// The sRGB transfer of IEC 61966-2-1 (colour textures, 8-bit files), evaluated by the
// built-in config's "sRGB" space, so textures and previews share one definition.
float srgb_to_linear(float encoded);
float linear_to_srgb(float linear);
// Decodes an sRGB-encoded image in place: colour channels only (gray or RGB), never
// alpha (glTF 2.0, section 3.9.2: alpha is linear).
void decode_srgb(Image& image);

}  // namespace penumbra
