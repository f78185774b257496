#include "io/image/image_reader.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>

#include "core/error.h"
#include "io/color/color.h"
#include "io/image/image_header.h"
#include "io/image/ktx2_container.h"
#include "io/image/ktx2_decoder.h"

namespace penumbra {

namespace {

// OIIO picks a reader from the file name's extension; bytes from a glTF buffer have
// no name, so the format is recognised from its signature instead.
const char* sniff_extension(const std::vector<uint8_t>& b) {
    auto starts = [&](const char* magic, size_t offset = 0) {
        const size_t n = std::strlen(magic);
        return b.size() >= offset + n && std::memcmp(b.data() + offset, magic, n) == 0;
    };
    if (starts("\x89PNG")) return "png";
    if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return "jpg";
    if (starts("RIFF") && starts("WEBP", 8)) return "webp";
    if (starts("GIF8")) return "gif";
    if (starts("BM")) return "bmp";
    if (starts("\x76\x2f\x31\x01")) return "exr";
    if (starts("#?RADIANCE") || starts("#?RGBE")) return "hdr";
    if (starts("II*") || starts("MM\x00*")) return "tif";
    return nullptr;
}

// The format to ask OIIO for pixels of `type`: UNKNOWN (the file's own) when that is
// `type`. OIIO 2.4 reads an explicitly named format, even the file's own, through a
// conversion buffer of tens of megabytes whatever the image's size; the file's own format
// goes straight into ours (a 64x64 PNG: 0.10 ms instead of 0.16 ms, and under ASan
// 0.24 ms instead of 17 ms).
OIIO::TypeDesc read_format(const OIIO::ImageSpec& spec, OIIO::TypeDesc type) {
    return spec.format == type && spec.channelformats.empty() ? OIIO::TypeDesc::UNKNOWN : type;
}

// One line, for SceneError: OIIO's messages may span several.
std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s.empty() ? "unknown error" : s;
}

std::string too_large(uint32_t w, uint32_t h, uint64_t max_pixels) {
    return std::to_string(w) + "x" + std::to_string(h) + " is more than the limit of " +
           std::to_string(max_pixels) + " pixels (--max-texture-pixels)";
}

// Opens the bytes with OIIO's reader for `ext`, refusing more than max_pixels before
// reading pixels, and returns what read(input, spec, channels) makes of them. OIIO's
// readers throw on some corrupt data (the GIF reader std::length_error), so anything
// they throw becomes an ImageDecodeError naming the image.
template <class Read>
auto decode_with(const std::vector<uint8_t>& bytes, const std::string& name, const char* ext,
                 uint64_t max_pixels, Read read) {
    try {
        OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
        auto in = OIIO::ImageInput::create(ext, false, nullptr, &proxy);
        OIIO::ImageSpec spec_in, config;
        // glTF's alpha is unassociated (straight): OIIO would otherwise premultiply the
        // colour of PNGs (and other straight-alpha formats) by it while reading.
        config.attribute("oiio:UnassociatedAlpha", 1);
        if (!in || !in->supports("ioproxy"))
            throw ImageDecodeError(name, std::string("no reader for format '") + ext + "'");
        if (!in->set_ioproxy(&proxy)) throw ImageDecodeError(name, one_line(in->geterror()));
        {
            // Headers are opened one at a time: OIIO 2.4's JPEG reader decodes ICC
            // profiles (decode_icc_profile, inside open) through state that threads
            // share; two of chess-board.glb's textures opened at once freed the same
            // block twice under ASan. Pixels still decode in parallel.
            static std::mutex open_mutex;
            std::lock_guard<std::mutex> lock(open_mutex);
            if (!in->open(std::string("memory.") + ext, spec_in, config))
                throw ImageDecodeError(name, one_line(in->geterror()));
        }

        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
            throw ImageDecodeError(name, "empty image");
        // A corrupt header can claim any size; refuse rather than die allocating it.
        if (uint64_t(spec.width) * uint64_t(spec.height) > max_pixels)
            throw ImageDecodeError(
                name, too_large(uint32_t(spec.width), uint32_t(spec.height), max_pixels));
        // More than RGBA (e.g. EXR layers) is cut to the first four channels.
        auto result = read(*in, spec, std::min(spec.nchannels, 4));
        in->close();
        return result;
    } catch (const ImageDecodeError&) {
        throw;
    } catch (const std::exception& e) {
        throw ImageDecodeError(
            name, std::string("the ") + ext + " decoder failed (" + one_line(e.what()) + ")");
    }
}

Image decode_float(const std::vector<uint8_t>& bytes, const std::string& name, const char* ext,
                   ImageEncoding encoding, uint64_t max_pixels) {
    return decode_with(
        bytes, name, ext, max_pixels,
        [&](OIIO::ImageInput& in, const OIIO::ImageSpec& spec, int channels) {
            Image img(spec.width, spec.height, channels);
            img.name = name;
            if (!in.read_image(0, 0, 0, channels, read_format(spec, OIIO::TypeDesc::FLOAT),
                               img.pixels.data()))
                throw ImageDecodeError(name, one_line(in.geterror()));
            // The transfer applies to colour, never to alpha (glTF 2.0,
            // section 3.9.2).
            if (encoding == ImageEncoding::Srgb) decode_srgb(img);
            return img;
        });
}

// The file's own precision: 8-bit and 16-bit files are read straight into texel storage
// of that size (never through float, which would cost 4 bytes a channel at the peak);
// anything else (float, half, 32-bit) as float. The pyramid's levels are allocated with
// level 0, so nothing is copied afterwards.
TextureImage decode_texels(const std::vector<uint8_t>& bytes, const std::string& name,
                           const char* ext, ImageEncoding encoding, uint64_t max_pixels,
                           bool mipmaps) {
    return decode_with(
        bytes, name, ext, max_pixels,
        [&](OIIO::ImageInput& in, const OIIO::ImageSpec& spec, int channels) {
            const OIIO::TypeDesc::BASETYPE base = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
            const bool is8 = base == OIIO::TypeDesc::UINT8 || base == OIIO::TypeDesc::INT8;
            const bool is16 = base == OIIO::TypeDesc::UINT16 || base == OIIO::TypeDesc::INT16;
            const TexelFormat format = is8    ? TexelFormat::U8
                                       : is16 ? TexelFormat::U16
                                              : TexelFormat::F32;
            const OIIO::TypeDesc type = is8    ? OIIO::TypeDesc::UINT8
                                        : is16 ? OIIO::TypeDesc::UINT16
                                               : OIIO::TypeDesc::FLOAT;
            const bool srgb = encoding == ImageEncoding::Srgb;
            TextureImage img(spec.width, spec.height, channels, format, srgb, mipmaps);
            if (!in.read_image(0, 0, 0, channels, read_format(spec, type), img.level0_data()))
                throw ImageDecodeError(name, one_line(in.geterror()));
            if (format == TexelFormat::F32 && srgb) {
                // Float colour data with the sRGB transfer (not a glTF format, but OIIO
                // may report one): decoded now, as float storage holds linear values.
                float* p = static_cast<float*>(img.level0_data());
                const size_t n = size_t(spec.width) * size_t(spec.height);
                for (size_t i = 0; i < n; ++i)
                    for (int c = 0; c < std::min(channels, 3); ++c)
                        if (!(channels == 2 && c == 1))
                            p[i * size_t(channels) + size_t(c)] =
                                srgb_to_linear(p[i * size_t(channels) + size_t(c)]);
            }
            img.build_mips();
            return img;
        });
}

}  // namespace

TextureImage decode_texture_image(const std::vector<uint8_t>& bytes, const std::string& name,
                                  ImageEncoding encoding, const TextureDecodeLimits& limits,
                                  bool mipmaps) {
    if (bytes.empty()) throw ImageDecodeError(name, "no data");
    // KTX2 only under KHR_texture_basisu; elsewhere it is refused as any other format.
    if (limits.allow_ktx2 && is_ktx2(bytes.data(), bytes.size()))
        return decode_ktx2(bytes, name, limits.max_pixels, mipmaps);
    const ImageHeader h = read_image_header(bytes, limits.allow_webp);
    // The size first: a header claiming too much is refused for that, whatever follows.
    if (h.format != ImageFormat::Unknown && uint64_t(h.width) * h.height > limits.max_pixels)
        throw ImageDecodeError(name, too_large(h.width, h.height, limits.max_pixels));
    if (!h.problem.empty()) throw ImageDecodeError(name, h.problem);
    TextureImage img =
        decode_texels(bytes, name, image_extension(h.format), encoding, limits.max_pixels, mipmaps);
    if (uint32_t(img.width()) != h.width || uint32_t(img.height()) != h.height)
        throw ImageDecodeError(name, "the header says " + std::to_string(h.width) + "x" +
                                         std::to_string(h.height) + ", the decoder " +
                                         std::to_string(img.width()) + "x" +
                                         std::to_string(img.height()));
    return img;
}

Image decode_image(const std::vector<uint8_t>& bytes, const std::string& name,
                   ImageEncoding encoding) {
    if (bytes.empty()) throw ImageDecodeError(name, "no data");
    const char* ext = sniff_extension(bytes);
    if (!ext) {
        // Not a signature we know: let OIIO go by the name's extension, if it has one.
        const size_t dot = name.find_last_of('.');
        const bool has_ext = dot != std::string::npos && name.size() - dot >= 2 &&
                             name.size() - dot <= 6 &&
                             std::all_of(name.begin() + long(dot) + 1, name.end(),
                                         [](char c) { return std::isalnum((unsigned char)c); });
        if (!has_ext) throw ImageDecodeError(name, "unrecognised format");
        ext = name.c_str() + dot + 1;
    }
    return decode_float(bytes, name, ext, encoding, kDefaultMaxTexturePixels);
}

Image read_image(const std::string& path, ImageEncoding encoding) {
    std::error_code ec;
    std::ifstream file(path, std::ios::binary);
    if (!std::filesystem::is_regular_file(path, ec) || !file)
        throw SceneError(path + ": cannot open file");
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                               std::istreambuf_iterator<char>());
    if (file.bad()) throw SceneError(path + ": cannot read file");
    return decode_image(bytes, path, encoding);
}

}  // namespace penumbra
