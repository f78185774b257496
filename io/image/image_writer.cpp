#include "io/image/image_writer.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/error.h"
#include "io/atomic_file.h"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

void write_with_oiio(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                     const void* data, const std::string& shown) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw SceneError(shown + ": cannot write: " + OIIO::geterror());
    if (!out->open(path, spec) || !out->write_image(type, data) || !out->close())
        throw SceneError(shown + ": cannot write: " + out->geterror());
}

// An RGBA image whose alpha is below 1 somewhere (a transparent background's coverage).
bool has_partial_alpha(const Image& image) {
    if (image.channels != 4) return false;
    for (size_t i = 3; i < image.pixels.size(); i += 4)
        if (image.pixels[i] < 1) return true;
    return false;
}

// Premultiplied RGBA to straight colour, as PNG stores it (0 where alpha is 0), so that
// the display transform sees the surface's own colour at partly covered pixels.
Image unpremultiplied(const Image& image) {
    Image out = image;
    for (size_t i = 0; i < out.pixels.size(); i += 4) {
        const float a = out.pixels[i + 3];
        for (size_t c = 0; c < 3; ++c) out.pixels[i + c] = a > 0 ? out.pixels[i + c] / a : 0.0f;
    }
    return out;
}

// OIIO takes matrices as Imath stores them: row vectors, so ours transposed.
void set_attribute(OIIO::ImageSpec& spec, const std::string& key, const MetadataValue& value) {
    if (const auto* s = std::get_if<std::string>(&value)) {
        spec.attribute(key, *s);
    } else if (const auto* i = std::get_if<int>(&value)) {
        spec.attribute(key, *i);
    } else if (const auto* f = std::get_if<float>(&value)) {
        spec.attribute(key, *f);
    } else if (const auto* d = std::get_if<double>(&value)) {
        spec.attribute(key, OIIO::TypeDesc::DOUBLE, d);
    } else if (const auto* m = std::get_if<Mat4>(&value)) {
        float v[16];
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) v[4 * r + c] = (*m)(c, r);
        spec.attribute(key, OIIO::TypeMatrix44, v);
    } else if (const auto* ch = std::get_if<Chromaticities>(&value)) {
        const float v[8] = {ch->red[0],  ch->red[1],  ch->green[0], ch->green[1],
                            ch->blue[0], ch->blue[1], ch->white[0], ch->white[1]};
        spec.attribute(key, OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), v);
    }
}

}  // namespace

const std::vector<std::string>& exr_compressions() {
    static const std::vector<std::string> list = {"none",  "rle", "zips", "zip",  "piz",
                                                  "pxr24", "b44", "b44a", "dwaa", "dwab"};
    return list;
}

void write_exr(const std::string& path, const std::vector<ExrLayer>& layers,
               const Metadata& metadata, const ExrOptions& options) {
    const auto& known = exr_compressions();
    // OIIO would silently fall back to zip for a name it does not know.
    if (std::find(known.begin(), known.end(), options.compression) == known.end())
        throw SceneError(path + ": unknown EXR compression '" + options.compression + "'");
    if (layers.empty() || !layers[0].image) throw SceneError(path + ": nothing to write");
    const int w = layers[0].image->width, h = layers[0].image->height;
    OIIO::ImageSpec spec(w, h, 0, OIIO::TypeDesc::FLOAT);
    spec.channelnames.clear();
    for (const ExrLayer& layer : layers) {
        if (!layer.image || layer.image->width != w || layer.image->height != h ||
            size_t(layer.image->channels) != layer.channels.size())
            throw SceneError(path + ": layer '" + layer.name + "' does not fit the image");
        const OIIO::TypeDesc type =
            options.half && !layer.full_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
        for (const std::string& c : layer.channels) {
            const std::string name = layer.name.empty() ? c : layer.name + "." + c;
            if (name == "A") spec.alpha_channel = int(spec.channelnames.size());
            spec.channelnames.push_back(name);
            spec.channelformats.push_back(type);
        }
    }
    spec.nchannels = int(spec.channelnames.size());
    // One format for all channels lets OIIO drop the per-channel list.
    if (std::all_of(spec.channelformats.begin(), spec.channelformats.end(),
                    [&](OIIO::TypeDesc t) { return t == spec.channelformats[0]; })) {
        spec.format = spec.channelformats[0];
        spec.channelformats.clear();
    }
    spec.attribute("compression", options.compression);
    // OIIO stamps the current time into EXRs unless DateTime is set; an empty value
    // suppresses it, so the same render command gives a bitwise identical file.
    spec.attribute("DateTime", "");
    for (const auto& [key, value] : metadata) set_attribute(spec, key, value);

    // Interleave every layer into one float buffer; OIIO converts to half per channel.
    const size_t n = size_t(w) * h, nc = size_t(spec.nchannels);
    std::vector<float> data(n * nc);
    size_t offset = 0;
    for (const ExrLayer& layer : layers) {
        const int lc = layer.image->channels;
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < lc; ++c)
                data[i * nc + offset + c] = layer.image->pixels[i * lc + c];
        offset += size_t(lc);
    }
    write_file_atomically(path, [&](const std::string& tmp) {
        write_with_oiio(tmp, spec, OIIO::TypeDesc::FLOAT, data.data(), path);
    });
}

void write_exr(const std::string& path, const Image& image, const Metadata& metadata) {
    static const std::vector<std::string> rgba = {"R", "G", "B", "A"};
    if (image.channels != 3 && image.channels != 4)
        throw SceneError(path + ": an EXR beauty needs 3 or 4 channels");
    const ExrLayer beauty{"", {rgba.begin(), rgba.begin() + image.channels}, &image, false};
    write_exr(path, {beauty}, metadata);
}

void write_preview(const std::string& path, const Image& image, const ColorPipeline& color,
                   float exposure) {
    // JPEG has no alpha: there the premultiplied colour shows the image over black.
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    const bool alpha = ext == ".png" && has_partial_alpha(image);
    const Image display = color.to_display(alpha ? unpremultiplied(image) : image, exposure);
    const int channels = alpha ? 4 : 3;
    const size_t n = size_t(display.width) * display.height;
    std::vector<unsigned char> bytes(n * channels);
    auto byte = [](float v) { return static_cast<unsigned char>(std::lround(v * 255.0f)); };
    for (size_t p = 0; p < n; ++p) {
        for (int c = 0; c < 3; ++c) bytes[p * channels + c] = byte(display.pixels[p * 3 + c]);
        if (alpha) bytes[p * 4 + 3] = byte(std::clamp(image.pixels[p * 4 + 3], 0.0f, 1.0f));
    }
    OIIO::ImageSpec spec(display.width, display.height, channels, OIIO::TypeDesc::UINT8);
    // The colour is straight already: OIIO would otherwise take it as premultiplied and
    // divide it by alpha once more.
    if (alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
    // Tells PNG readers the curve (an sRGB chunk); other displays' encodings have no
    // PNG tag OIIO would write, so they get none rather than a wrong one.
    std::string display_name = color.display();
    std::transform(display_name.begin(), display_name.end(), display_name.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (display_name.find("srgb") != std::string::npos) spec.attribute("oiio:ColorSpace", "sRGB");
    write_file_atomically(path, [&](const std::string& tmp) {
        write_with_oiio(tmp, spec, OIIO::TypeDesc::UINT8, bytes.data(), path);
    });
}

void write_preview(const std::string& path, const Image& image, float exposure) {
    write_preview(path, image, ColorPipeline::builtin(), exposure);
}

std::string preview_path_for(const std::string& output_path) {
    return fs::path(output_path).replace_extension(".png").string();
}

}  // namespace penumbra
