#include "io/image_reader.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "io/color.h"
#include "io/image_header.h"

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

// Decodes with OIIO's reader for `ext`, refusing more than max_pixels before reading
// pixels. OIIO's readers throw on some corrupt data (the GIF reader std::length_error),
// so anything they throw becomes an ImageDecodeError naming the image.
Image decode_with(const std::vector<uint8_t>& bytes, const std::string& name, const char* ext,
                  ImageEncoding encoding, uint64_t max_pixels) {
    try {
        OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
        auto in = OIIO::ImageInput::create(ext, false, nullptr, &proxy);
        OIIO::ImageSpec spec_in;
        if (!in || !in->supports("ioproxy"))
            throw ImageDecodeError(name, std::string("no reader for format '") + ext + "'");
        if (!in->set_ioproxy(&proxy) || !in->open(std::string("memory.") + ext, spec_in))
            throw ImageDecodeError(name, one_line(in->geterror()));

        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
            throw ImageDecodeError(name, "empty image");
        // A corrupt header can claim any size; refuse rather than die allocating it.
        if (uint64_t(spec.width) * uint64_t(spec.height) > max_pixels)
            throw ImageDecodeError(
                name, too_large(uint32_t(spec.width), uint32_t(spec.height), max_pixels));
        // More than RGBA (e.g. EXR layers) is cut to the first four channels.
        const int channels = std::min(spec.nchannels, 4);
        Image img(spec.width, spec.height, channels);
        img.name = name;
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
            throw ImageDecodeError(name, one_line(in->geterror()));
        in->close();
        // The transfer applies to colour, never to alpha (glTF 2.0, section 3.9.2).
        if (encoding == ImageEncoding::Srgb) decode_srgb(img);
        return img;
    } catch (const ImageDecodeError&) {
        throw;
    } catch (const std::exception& e) {
        throw ImageDecodeError(
            name, std::string("the ") + ext + " decoder failed (" + one_line(e.what()) + ")");
    }
}

}  // namespace

Image decode_texture_image(const std::vector<uint8_t>& bytes, const std::string& name,
                           ImageEncoding encoding, const TextureDecodeLimits& limits) {
    if (bytes.empty()) throw ImageDecodeError(name, "no data");
    const ImageHeader h = read_image_header(bytes, limits.allow_webp);
    // The size first: a header claiming too much is refused for that, whatever follows.
    if (h.format != ImageFormat::Unknown && uint64_t(h.width) * h.height > limits.max_pixels)
        throw ImageDecodeError(name, too_large(h.width, h.height, limits.max_pixels));
    if (!h.problem.empty()) throw ImageDecodeError(name, h.problem);
    Image img = decode_with(bytes, name, image_extension(h.format), encoding, limits.max_pixels);
    if (uint32_t(img.width) != h.width || uint32_t(img.height) != h.height)
        throw ImageDecodeError(name, "the header says " + std::to_string(h.width) + "x" +
                                         std::to_string(h.height) + ", the decoder " +
                                         std::to_string(img.width) + "x" +
                                         std::to_string(img.height));
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
    return decode_with(bytes, name, ext, encoding, kDefaultMaxTexturePixels);
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
