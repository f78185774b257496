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

namespace penumbra {

namespace {

constexpr size_t kMaxPixels = size_t(1) << 28;  // 16k x 16k

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

}  // namespace

Image decode_image(const std::vector<uint8_t>& bytes, const std::string& name,
                   ImageEncoding encoding) {
    if (bytes.empty()) throw SceneError(name + ": cannot decode image: no data");
    const char* ext = sniff_extension(bytes);
    if (!ext) {
        // Not a signature we know: let OIIO go by the name's extension, if it has one.
        const size_t dot = name.find_last_of('.');
        const bool has_ext = dot != std::string::npos && name.size() - dot >= 2 &&
                             name.size() - dot <= 6 &&
                             std::all_of(name.begin() + long(dot) + 1, name.end(),
                                         [](char c) { return std::isalnum((unsigned char)c); });
        if (!has_ext) throw SceneError(name + ": cannot decode image: unrecognised format");
        ext = name.c_str() + dot + 1;
    }
    OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::create(ext, false, nullptr, &proxy);
    OIIO::ImageSpec spec_in;
    if (!in || !in->supports("ioproxy"))
        throw SceneError(name + ": cannot decode image: no reader for format '" + ext + "'");
    if (!in->set_ioproxy(&proxy) || !in->open(std::string("memory.") + ext, spec_in))
        throw SceneError(name + ": cannot decode image: " + one_line(in->geterror()));

    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throw SceneError(name + ": cannot decode image: empty image");
    // A corrupt header can claim any size; refuse rather than die allocating it.
    if (size_t(spec.width) * size_t(spec.height) > kMaxPixels)
        throw SceneError(name + ": cannot decode image: " + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + " is too large");
    // More than RGBA (e.g. EXR layers) is cut to the first four channels.
    const int channels = std::min(spec.nchannels, 4);
    Image img(spec.width, spec.height, channels);
    img.name = name;
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
        throw SceneError(name + ": cannot decode image: " + one_line(in->geterror()));
    in->close();

    // The transfer applies to colour, never to alpha (glTF 2.0, section 3.9.2).
    if (encoding == ImageEncoding::Srgb) decode_srgb(img);
    return img;
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
