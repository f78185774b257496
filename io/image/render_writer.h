// The files of a finished render: one EXR (the beauty in the output colour space, AOV
// layers, and a header that describes the render: colour space and chromaticities,
// camera matrices, error against a reference) and the display-referred preview.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/denoise/denoise_input.h"
#include "core/film/film.h"
#include "core/scene/scene.h"
#include "io/color/color.h"
#include "io/image/image_writer.h"

namespace penumbra {

// A denoised beauty (core/denoise/nfor_denoiser.h's result) to write in place of the
// film's own estimate.
struct DenoisedBeauty {
    const Image* color = nullptr;       // 3 channels, working space, the film's size
    std::string method;                 // the method and its parameters: describe(params)
    double relmse_estimate = 0;         // the denoiser's estimate of color's relMSE
    double relmse_estimate_stderr = 0;  // that estimate's standard error
    double firefly_energy = 0;          // the share of energy its firefly guard held back
};

struct RenderFiles {
    std::string exr;      // the EXR's path
    std::string preview;  // the PNG/JPEG's path; empty: none
    float exposure = 0;   // stops: the beauty (EXR and preview) is scaled by 2^exposure
    ExrOptions exr_options;
    std::string reference;  // EXR to compare with (same size, output colour space); empty: none
    // Set: the EXR's RGB and the preview show this image (alpha stays the film's), the
    // film's unbiased estimate becomes the layer Noisy.R/G/B (exposed and converted as
    // the RGB is), and the header gets "penumbra:denoise" (the method) and
    // "penumbra:denoise_relmse_estimate".
    const DenoisedBeauty* denoised = nullptr;
    // Set (a row band of a farm render that denoises): the beauty stays the film's, and
    // the denoiser's input is added as full-float layers (io/image/denoise_layers.h), from which
    // the farm's merge denoises the assembled image.
    const DenoiseInput* denoise_input = nullptr;
};

struct RenderFilesResult {
    // Against RenderFiles::reference: of the EXR's RGB (the denoised image when there is
    // one) and, when denoised, of the Noisy layer.
    std::optional<double> mse, relmse;
    std::optional<double> noisy_mse, noisy_relmse;
};

// Writes the EXR and the preview of film (rendered in color's working space), its beauty
// scaled by 2^exposure (and the variance AOV by its square), and returns the error of the
// exposed beauty against the reference. metadata is the caller's (scene, integrator,
// spp, ...); color_metadata, camera_metadata, the denoiser's fields and the reference's
// errors ("penumbra:mse", "penumbra:relmse", and when denoised "penumbra:noisy_mse" and
// "penumbra:noisy_relmse") are added. Throws SceneError for a reference that cannot be
// read or does not match in size.
RenderFilesResult write_render(const RenderFiles& files, const Film& film,
                               const ColorPipeline& color, const CameraDesc& camera,
                               Metadata metadata);

// A render's beauty as its files hold it, made from a working-space RGBA image: scaled by
// 2^exposure (colour, not alpha) for the preview, and that in the output space for the
// EXR. write_render and the farm's merge both make theirs here, so they agree bit for bit.
struct Beauty {
    Image working;  // RGBA, exposed, working space: what write_preview takes
    Image output;   // RGBA, exposed, output space: the EXR's R, G, B, A
};
Beauty make_beauty(Image working, float exposure, const ColorPipeline& color);
// The beauty of a denoised render: denoised's colour (working space, 3 channels) with
// alpha's alpha (channel 3 of an RGBA image the same size; its colour is not read), and
// black where that alpha is 0 (no camera ray covered the pixel).
Beauty denoised_beauty(const DenoisedBeauty& denoised, const Image& alpha, float exposure,
                       const ColorPipeline& color);
// The header strings of a denoised render: "penumbra:denoise" (the method) and
// "penumbra:denoise_relmse_estimate" (every digit of the double).
std::vector<std::pair<std::string, std::string>> denoise_attributes(const DenoisedBeauty& denoised);

// The EXR layers of film's AOVs, named as Blender's compositor and Nuke expect a
// "pass.channel" pair: Albedo.{R,G,B}, Normal.{X,Y,Z}, Depth.Z, Position.{X,Y,Z},
// Variance.{R,G,B}, Samples.X, Error.X (relative standard error, Film::relative_error).
// Albedo is converted to the output space (a colour);
// variance stays in the working space (a matrix does not map variances of correlated
// channels). Depth, position and samples stay 32-bit under --half.
struct AovLayers {
    std::vector<Image> images;  // owned; layers point into it
    std::vector<ExrLayer> layers;
};
// radiance_scale multiplies the variance (by its square), as an exposure scales the beauty.
AovLayers aov_layers(const Film& film, const ColorPipeline& color, float radiance_scale = 1);

// "penumbra:colorspace" (the output space's name), "chromaticities" when known,
// "penumbra:working_space" and "penumbra:ocio_config".
Metadata color_metadata(const ColorPipeline& color);
// "penumbra:camera", "worldtocamera" and "worldtoNDC" (OpenEXR's worldToCamera and
// worldToNDC), for a width x height image.
Metadata camera_metadata(const CameraDesc& camera, int width, int height);
// The beauty channels (R, G, B and A if present, found by name) of an EXR, for a
// reference. Throws SceneError when it cannot be read or has no R, G, B.
Image read_beauty(const std::string& path);

}  // namespace penumbra
