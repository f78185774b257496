#include "io/band_merge.h"

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <memory>

#include "core/error.h"
#include "io/atomic_file.h"

namespace penumbra {

namespace {

// Float holds every half and float exactly, so reading EXRs as float and writing them
// with the file's channel formats copies the bits; 8-bit previews are read as bytes.
OIIO::TypeDesc buffer_type(const OIIO::ImageSpec& spec) {
    return spec.format == OIIO::TypeDesc::UINT8 && spec.channelformats.empty()
               ? OIIO::TypeDesc::UINT8
               : OIIO::TypeDesc::FLOAT;
}

}  // namespace

void merge_bands(const std::vector<BandFile>& bands, const std::string& output,
                 const std::vector<std::pair<std::string, std::string>>& attributes) {
    if (bands.empty()) throw SceneError(output + ": no bands to merge");
    OIIO::ImageSpec spec;
    std::vector<unsigned char> pixels;
    size_t row_bytes = 0;
    for (size_t b = 0; b < bands.size(); ++b) {
        const BandFile& band = bands[b];
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(band.path);
        if (!in) throw SceneError(band.path + ": cannot read the band: " + OIIO::geterror());
        const OIIO::ImageSpec& s = in->spec();
        if (b == 0) {
            spec = s;
            row_bytes = size_t(s.width) * s.nchannels * buffer_type(s).size();
            pixels.assign(row_bytes * size_t(s.height), 0);
        } else if (s.width != spec.width || s.height != spec.height ||
                   s.channelnames != spec.channelnames) {
            throw SceneError(band.path + ": the band's size or channels differ from " +
                             bands[0].path + "'s");
        }
        if (band.row_begin < 0 || band.row_end > s.height || band.row_begin > band.row_end)
            throw SceneError(band.path + ": rows " + std::to_string(band.row_begin) + "-" +
                             std::to_string(band.row_end) + " are outside the image");
        std::vector<unsigned char> all(row_bytes * size_t(s.height));
        if (!in->read_image(0, 0, 0, s.nchannels, buffer_type(spec), all.data()))
            throw SceneError(band.path + ": cannot read the band: " + in->geterror());
        std::memcpy(&pixels[row_bytes * size_t(band.row_begin)],
                    &all[row_bytes * size_t(band.row_begin)],
                    row_bytes * size_t(band.row_end - band.row_begin));
    }
    // As write_exr: no DateTime, so the merge of a render is as reproducible as the render.
    spec.attribute("DateTime", "");
    for (const auto& [key, value] : attributes) spec.attribute(key, value);
    write_file_atomically(output, [&](const std::string& tmp) {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(tmp);
        if (!out) throw SceneError(output + ": cannot write: " + OIIO::geterror());
        if (!out->open(tmp, spec) || !out->write_image(buffer_type(spec), pixels.data()) ||
            !out->close())
            throw SceneError(output + ": cannot write: " + out->geterror());
    });
}

int image_height(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        OIIO::geterror();
        return -1;
    }
    return in->spec().height;
}

std::string image_attribute(const std::string& path, const std::string& key,
                            const std::string& fallback) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        OIIO::geterror();
        return fallback;
    }
    return in->spec().get_string_attribute(key, fallback);
}

}  // namespace penumbra
