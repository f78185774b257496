#include "io/image_writer.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include "core/error.h"
#include "io/image_reader.h"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

// Writes through `write` into a temporary sibling of path, then renames it into place.
template <typename WriteFn>
void write_atomically(const std::string& path, WriteFn write) {
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    fs::create_directories(dir, ec);
    // Keep the extension last: OIIO picks the format from it.
    const fs::path tmp = dir / (".tmp-" + std::to_string(getpid()) + "-" +
                                target.filename().string());
    try {
        write(tmp.string());
    } catch (...) {
        fs::remove(tmp, ec);
        throw;
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw SceneError(path + ": cannot move the finished file into place: " + ec.message());
    }
}

void write_with_oiio(const std::string& path, const OIIO::ImageSpec& spec,
                     OIIO::TypeDesc type, const void* data, const std::string& shown) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw SceneError(shown + ": cannot write: " + OIIO::geterror());
    if (!out->open(path, spec) || !out->write_image(type, data) || !out->close())
        throw SceneError(shown + ": cannot write: " + out->geterror());
}

}  // namespace

void write_exr(const std::string& path, const Image& image, const Metadata& metadata) {
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
    if (image.channels == 4) spec.channelnames = {"R", "G", "B", "A"};
    if (image.channels == 3) spec.channelnames = {"R", "G", "B"};
    spec.alpha_channel = image.channels == 4 ? 3 : -1;
    spec.attribute("compression", "zip");
    spec.attribute("oiio:ColorSpace", "Linear");
    // OIIO stamps the current time into EXRs unless DateTime is set; an empty value
    // suppresses it, so the same render command gives a bitwise identical file.
    spec.attribute("DateTime", "");
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    write_atomically(path, [&](const std::string& tmp) {
        write_with_oiio(tmp, spec, OIIO::TypeDesc::FLOAT, image.pixels.data(), path);
    });
}

void write_preview(const std::string& path, const Image& image, float exposure) {
    const int channels = std::min(image.channels, 3);
    std::vector<unsigned char> bytes(size_t(image.width) * image.height * channels);
    const float scale = std::exp2(exposure);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.at(x, y);
            for (int c = 0; c < channels; ++c) {
                float v = p[c] * scale;
                v = std::isfinite(v) ? linear_to_srgb(std::clamp(v, 0.0f, 1.0f)) : 0.0f;
                bytes[(size_t(y) * image.width + x) * channels + c] =
                    static_cast<unsigned char>(std::lround(v * 255.0f));
            }
        }
    OIIO::ImageSpec spec(image.width, image.height, channels, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    write_atomically(path, [&](const std::string& tmp) {
        write_with_oiio(tmp, spec, OIIO::TypeDesc::UINT8, bytes.data(), path);
    });
}

std::string preview_path_for(const std::string& output_path) {
    return fs::path(output_path).replace_extension(".png").string();
}

}  // namespace penumbra
