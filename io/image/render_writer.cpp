#include "io/image/render_writer.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/camera/camera_matrices.h"
#include "core/film/cryptomatte.h"
#include "core/film/image_error.h"
#include "core/error.h"
#include "io/image/denoise_layers.h"

namespace penumbra {

namespace {

struct AovLayout {
    Aov aov;
    const char* layer;
    std::vector<std::string> channels;
    bool colour;      // converted to the output space
    bool full_float;  // precision or range beyond half's
};

const std::vector<AovLayout>& aov_layouts() {
    static const std::vector<AovLayout> list = {
        {Aov::Albedo, "Albedo", {"R", "G", "B"}, true, false},
        {Aov::Normal, "Normal", {"X", "Y", "Z"}, false, false},
        // Blender names its depth pass "Depth" with channel Z.
        {Aov::Depth, "Depth", {"Z"}, false, true},
        {Aov::Position, "Position", {"X", "Y", "Z"}, false, true},
        {Aov::Variance, "Variance", {"R", "G", "B"}, false, false},
        // Half holds integers exactly only up to 2048.
        {Aov::Samples, "Samples", {"X"}, false, true},
        // Relative, so an exposure leaves it as it is.
        {Aov::Error, "Error", {"X"}, false, false},
        // Integers in float channels, as Cycles writes IndexOB and IndexMA and Blender's
        // compositor and Nuke read ID passes; 32-bit, exact to 2^24.
        {Aov::ObjectId, "ObjectID", {"X"}, false, true},
        {Aov::MaterialId, "MaterialID", {"X"}, false, true},
        // Blender's Vector pass and channels; pixels, with sub-pixel precision beyond
        // half's in big images.
        {Aov::Vector, "Vector", {"X", "Y", "Z", "W"}, false, true},
    };
    return list;
}

// The exposure scales colour, not alpha.
void expose(Image& image, float scale) {
    if (scale == 1) return;
    for (size_t i = 0; i < image.pixels.size(); ++i)
        if (image.channels < 4 || i % size_t(image.channels) != 3) image.pixels[i] *= scale;
}

// Doubles as text with every digit a double holds, as the other penumbra: fields.
std::string full_precision(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// RGB of an RGB(A) image.
Image rgb_of(const Image& image) {
    Image out(image.width, image.height, 3);
    for (size_t p = 0; p < size_t(image.width) * image.height; ++p)
        for (int c = 0; c < 3; ++c)
            out.pixels[p * 3 + size_t(c)] = image.pixels[p * size_t(image.channels) + size_t(c)];
    return out;
}

Image read_reference(const std::string& path, const Image& beauty) {
    Image ref = read_beauty(path);
    if (ref.width != beauty.width || ref.height != beauty.height)
        throw SceneError(path + ": the reference is " + std::to_string(ref.width) + "x" +
                         std::to_string(ref.height) + ", the render " +
                         std::to_string(beauty.width) + "x" + std::to_string(beauty.height));
    return ref;
}

}  // namespace

Beauty make_beauty(Image working, float exposure, const ColorPipeline& color) {
    expose(working, std::exp2(exposure));
    Beauty beauty;
    beauty.output = working;
    color.to_output(beauty.output);
    beauty.working = std::move(working);
    return beauty;
}

Beauty denoised_beauty(const DenoisedBeauty& denoised, const Image& alpha, float exposure,
                       const ColorPipeline& color) {
    const Image& rgb = *denoised.color;
    CHECK(rgb.width == alpha.width && rgb.height == alpha.height && rgb.channels == 3 &&
              alpha.channels == 4,
          "denoised image " << rgb.width << "x" << rgb.height << "x" << rgb.channels << " for a "
                            << alpha.width << "x" << alpha.height << "x" << alpha.channels
                            << " beauty");
    Image working = alpha;
    // A pixel no camera ray covered (a transparent background's alpha 0) stays empty:
    // the denoiser's neighbourhood would otherwise leak the object's colour into it.
    for (size_t p = 0; p < size_t(rgb.width) * rgb.height; ++p)
        for (size_t c = 0; c < 3; ++c)
            working.pixels[p * 4 + c] = alpha.pixels[p * 4 + 3] == 0 ? 0.0f : rgb.pixels[p * 3 + c];
    return make_beauty(std::move(working), exposure, color);
}

std::vector<std::pair<std::string, std::string>> denoise_attributes(
    const DenoisedBeauty& denoised) {
    return {{"penumbra:denoise", denoised.method},
            {"penumbra:denoise_relmse_estimate", full_precision(denoised.relmse_estimate)},
            {"penumbra:denoise_relmse_estimate_stderr",
             full_precision(denoised.relmse_estimate_stderr)},
            {"penumbra:denoise_firefly_energy", full_precision(denoised.firefly_energy)}};
}

namespace {

// A Cryptomatte AOV's layers, Typename00 to 02: two ranks each, ID and coverage in R G and
// B A, 32-bit (the IDs are hashes in float bits).
void add_cryptomatte_layers(const Film& film, Aov aov, const char* name, AovLayers& out) {
    if (!film.aovs().has(aov)) return;
    const Image ranked = film.resolve_aov(aov);
    for (int layer = 0; layer < kCryptomatteRanks / 2; ++layer) {
        Image img(ranked.width, ranked.height, 4);
        for (size_t p = 0; p < size_t(img.width) * img.height; ++p)
            for (int c = 0; c < 4; ++c)
                img.pixels[p * 4 + size_t(c)] = ranked.pixels[p * ranked.channels + 4 * layer + c];
        out.images.push_back(std::move(img));
        char layer_name[64];
        std::snprintf(layer_name, sizeof layer_name, "%s%02d", name, layer);
        out.layers.push_back({layer_name, {"R", "G", "B", "A"}, &out.images.back(), true});
    }
}

}  // namespace

AovLayers aov_layers(const Film& film, const ColorPipeline& color, float radiance_scale) {
    AovLayers out;
    // Layers point into images: no reallocation.
    out.images.reserve(aov_layouts().size() + kCryptomatteRanks);
    for (const AovLayout& l : aov_layouts()) {
        if (!film.aovs().has(l.aov)) continue;
        out.images.push_back(film.resolve_aov(l.aov));
        if (l.colour) color.to_output(out.images.back());
        if (l.aov == Aov::Variance && radiance_scale != 1)
            for (float& v : out.images.back().pixels) v *= radiance_scale * radiance_scale;
        out.layers.push_back({l.layer, l.channels, &out.images.back(), l.full_float});
    }
    add_cryptomatte_layers(film, Aov::CryptoObject, kCryptoObjectLayer, out);
    add_cryptomatte_layers(film, Aov::CryptoMaterial, kCryptoMaterialLayer, out);
    return out;
}

Metadata color_metadata(const ColorPipeline& color) {
    // OIIO keeps "oiio:" attributes out of files (its EXR reader always reports
    // "Linear"), so the space's name travels in our own key.
    Metadata m = {
        {"penumbra:colorspace", color.output_space()},
        {"penumbra:working_space", color.working_space()},
        {"penumbra:ocio_config", color.config_source()},
    };
    if (color.output_chromaticities())
        m.push_back({"chromaticities", *color.output_chromaticities()});
    return m;
}

Metadata camera_metadata(const CameraDesc& camera, int width, int height) {
    return {
        {"penumbra:camera", camera.name},
        {"worldtocamera", world_to_camera_lh(camera)},
        {"worldtoNDC", world_to_ndc(camera, width, height)},
    };
}

Image read_beauty(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        throw SceneError(path + ": cannot read the reference: " + OIIO::geterror());
    }
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<int> index;
    for (const char* name : {"R", "G", "B", "A"}) {
        const int i = spec.channelindex(name);
        if (i < 0 && name[0] != 'A')
            throw SceneError(path + ": the reference has no channel " + name);
        if (i >= 0) index.push_back(i);
    }
    std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw SceneError(path + ": cannot read the reference: " + in->geterror());
    Image img(spec.width, spec.height, int(index.size()));
    for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p)
        for (size_t c = 0; c < index.size(); ++c)
            img.pixels[p * index.size() + c] = all[p * spec.nchannels + size_t(index[c])];
    return img;
}

RenderFilesResult write_render(const RenderFiles& files, const Film& film,
                               const ColorPipeline& color, const CameraDesc& camera,
                               Metadata metadata) {
    Image resolved = film.resolve();
    Beauty beauty, noisy;  // noisy: the film's own estimate when the denoiser replaced it
    if (files.denoised) {
        beauty = denoised_beauty(*files.denoised, resolved, files.exposure, color);
        noisy = make_beauty(std::move(resolved), files.exposure, color);
        for (auto& [key, value] : denoise_attributes(*files.denoised))
            metadata.push_back({key, value});
    } else {
        beauty = make_beauty(std::move(resolved), files.exposure, color);
    }

    RenderFilesResult result;
    if (!files.reference.empty()) {
        const Image ref = read_reference(files.reference, beauty.output);
        result.mse = mean_squared_error(beauty.output, ref);
        result.relmse = relative_mse(beauty.output, ref);
        metadata.push_back({"penumbra:reference", files.reference});
        metadata.push_back({"penumbra:mse", *result.mse});
        metadata.push_back({"penumbra:relmse", *result.relmse});
        metadata.push_back({"penumbra:relmse_epsilon", kRelMseEpsilon});
        if (files.denoised) {
            result.noisy_mse = mean_squared_error(noisy.output, ref);
            result.noisy_relmse = relative_mse(noisy.output, ref);
            metadata.push_back({"penumbra:noisy_mse", *result.noisy_mse});
            metadata.push_back({"penumbra:noisy_relmse", *result.noisy_relmse});
        }
    }
    for (auto& entry : color_metadata(color)) metadata.push_back(std::move(entry));
    for (auto& entry : camera_metadata(camera, film.width(), film.height()))
        metadata.push_back(std::move(entry));

    const AovLayers aovs = aov_layers(film, color, std::exp2(files.exposure));
    std::vector<ExrLayer> layers = {{"", {"R", "G", "B", "A"}, &beauty.output, false}};
    const Image noisy_rgb = files.denoised ? rgb_of(noisy.output) : Image();
    if (files.denoised) layers.push_back({"Noisy", {"R", "G", "B"}, &noisy_rgb, false});
    layers.insert(layers.end(), aovs.layers.begin(), aovs.layers.end());
    if (files.denoise_input) {
        const std::vector<ExrLayer> input = denoise_input_layers(*files.denoise_input);
        layers.insert(layers.end(), input.begin(), input.end());
    }
    write_exr(files.exr, layers, metadata, files.exr_options);
    if (!files.preview.empty()) write_preview(files.preview, beauty.working, color);
    return result;
}

}  // namespace penumbra
