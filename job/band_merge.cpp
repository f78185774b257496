#include "job/band_merge.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
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

struct MergedImage::Data {
    OIIO::ImageSpec spec;
    OIIO::TypeDesc type;  // of `pixels`: buffer_type(spec)
    std::vector<unsigned char> pixels;
    std::string source;  // the first band's file, for messages

    size_t pixel_count() const { return size_t(spec.width) * size_t(spec.height); }
    const float* floats() const { return reinterpret_cast<const float*>(pixels.data()); }
    float* floats() { return reinterpret_cast<float*>(pixels.data()); }
    // The channel's index; throws SceneError when there is none or the image is 8-bit.
    int float_channel(const std::string& name) const {
        if (type != OIIO::TypeDesc::FLOAT)
            throw SceneError(source + ": an 8-bit image has no float channel " + name);
        const int i = spec.channelindex(name);
        if (i < 0) throw SceneError(source + ": no channel " + name);
        return i;
    }
    // Rebuilds the channels as `order` lists them (indices of the current ones, -1 for a
    // new channel left 0) with these names and formats; alpha and depth follow by name.
    void relayout(const std::vector<int>& order, const std::vector<std::string>& names,
                  const std::vector<OIIO::TypeDesc>& formats);
};

void MergedImage::Data::relayout(const std::vector<int>& order,
                                 const std::vector<std::string>& names,
                                 const std::vector<OIIO::TypeDesc>& formats) {
    const size_t n = pixel_count(), old_nc = size_t(spec.nchannels), nc = order.size();
    std::vector<unsigned char> out(n * nc * sizeof(float), 0);
    float* dst = reinterpret_cast<float*>(out.data());
    for (size_t p = 0; p < n; ++p)
        for (size_t c = 0; c < nc; ++c)
            if (order[c] >= 0) dst[p * nc + c] = floats()[p * old_nc + size_t(order[c])];
    auto index_of = [&](int old) {
        if (old < 0) return -1;
        const auto it = std::find(names.begin(), names.end(), spec.channelnames[size_t(old)]);
        return it == names.end() ? -1 : int(it - names.begin());
    };
    spec.alpha_channel = index_of(spec.alpha_channel);
    spec.z_channel = index_of(spec.z_channel);
    spec.channelnames = names;
    spec.nchannels = int(nc);
    // As write_exr: one format for all channels drops the per-channel list.
    const bool uniform = std::all_of(formats.begin(), formats.end(),
                                     [&](OIIO::TypeDesc t) { return t == formats[0]; });
    spec.format = uniform ? formats[0] : OIIO::TypeDesc(OIIO::TypeDesc::FLOAT);
    spec.channelformats = uniform ? std::vector<OIIO::TypeDesc>() : formats;
    pixels = std::move(out);
}

MergedImage::MergedImage(const std::vector<BandFile>& bands) : m_data(std::make_unique<Data>()) {
    if (bands.empty()) throw SceneError("no bands to merge");
    Data& d = *m_data;
    d.source = bands[0].path;
    size_t row_bytes = 0;
    for (size_t b = 0; b < bands.size(); ++b) {
        const BandFile& band = bands[b];
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(band.path);
        if (!in) throw SceneError(band.path + ": cannot read the band: " + OIIO::geterror());
        const OIIO::ImageSpec& s = in->spec();
        if (b == 0) {
            d.spec = s;
            d.type = buffer_type(s);
            row_bytes = size_t(s.width) * s.nchannels * d.type.size();
            d.pixels.assign(row_bytes * size_t(s.height), 0);
        } else if (s.width != d.spec.width || s.height != d.spec.height ||
                   s.channelnames != d.spec.channelnames) {
            throw SceneError(band.path + ": the band's size or channels differ from " +
                             bands[0].path + "'s");
        }
        if (band.row_begin < 0 || band.row_end > s.height || band.row_begin > band.row_end)
            throw SceneError(band.path + ": rows " + std::to_string(band.row_begin) + "-" +
                             std::to_string(band.row_end) + " are outside the image");
        std::vector<unsigned char> all(row_bytes * size_t(s.height));
        if (!in->read_image(0, 0, 0, s.nchannels, d.type, all.data()))
            throw SceneError(band.path + ": cannot read the band: " + in->geterror());
        std::memcpy(&d.pixels[row_bytes * size_t(band.row_begin)],
                    &all[row_bytes * size_t(band.row_begin)],
                    row_bytes * size_t(band.row_end - band.row_begin));
    }
}

MergedImage::~MergedImage() = default;

int MergedImage::width() const { return m_data->spec.width; }
int MergedImage::height() const { return m_data->spec.height; }

Image MergedImage::channels(const std::vector<std::string>& names) const {
    const Data& d = *m_data;
    std::vector<int> index;
    for (const std::string& name : names) index.push_back(d.float_channel(name));
    Image out(d.spec.width, d.spec.height, int(names.size()));
    const size_t nc = size_t(d.spec.nchannels);
    for (size_t p = 0; p < d.pixel_count(); ++p)
        for (size_t c = 0; c < index.size(); ++c)
            out.pixels[p * index.size() + c] = d.floats()[p * nc + size_t(index[c])];
    return out;
}

void MergedImage::set_channels(const std::vector<std::string>& names, const Image& values) {
    Data& d = *m_data;
    CHECK(values.width == d.spec.width && values.height == d.spec.height &&
              size_t(values.channels) == names.size(),
          "values of " << values.channels << " channels for " << names.size() << " names");
    const size_t nc = size_t(d.spec.nchannels);
    for (size_t c = 0; c < names.size(); ++c) {
        const size_t i = size_t(d.float_channel(names[c]));
        for (size_t p = 0; p < d.pixel_count(); ++p)
            d.floats()[p * nc + i] = values.pixels[p * names.size() + c];
    }
}

void MergedImage::insert_channels(const std::string& after, const std::vector<std::string>& names,
                                  const std::string& like, const Image& values) {
    Data& d = *m_data;
    const int at = d.float_channel(after) + 1;
    const OIIO::TypeDesc format = d.spec.channelformat(d.float_channel(like));
    std::vector<int> order;
    std::vector<std::string> all;
    std::vector<OIIO::TypeDesc> formats;
    for (int c = 0; c <= d.spec.nchannels; ++c) {
        if (c == at)
            for (const std::string& name : names) {
                order.push_back(-1);
                all.push_back(name);
                formats.push_back(format);
            }
        if (c == d.spec.nchannels) break;
        order.push_back(c);
        all.push_back(d.spec.channelnames[size_t(c)]);
        formats.push_back(d.spec.channelformat(c));
    }
    d.relayout(order, all, formats);
    set_channels(names, values);
}

void MergedImage::remove_channels(const std::string& prefix) {
    Data& d = *m_data;
    std::vector<int> order;
    std::vector<std::string> kept;
    std::vector<OIIO::TypeDesc> formats;
    for (int c = 0; c < d.spec.nchannels; ++c) {
        const std::string& name = d.spec.channelnames[size_t(c)];
        if (name.rfind(prefix, 0) == 0) continue;
        order.push_back(c);
        kept.push_back(name);
        formats.push_back(d.spec.channelformat(c));
    }
    if (kept.size() == size_t(d.spec.nchannels)) return;
    if (kept.empty()) throw SceneError(d.source + ": no channels left without " + prefix);
    if (d.type != OIIO::TypeDesc::FLOAT)
        throw SceneError(d.source + ": an 8-bit image's channels cannot be left out");
    d.relayout(order, kept, formats);
}

void MergedImage::write(const std::string& output, const HeaderStrings& attributes) const {
    OIIO::ImageSpec spec = m_data->spec;
    // As write_exr: no DateTime, so the merge of a render is as reproducible as the render.
    spec.attribute("DateTime", "");
    for (const auto& [key, value] : attributes) spec.attribute(key, value);
    write_file_atomically(output, [&](const std::string& tmp) {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(tmp);
        if (!out) throw SceneError(output + ": cannot write: " + OIIO::geterror());
        if (!out->open(tmp, spec) || !out->write_image(m_data->type, m_data->pixels.data()) ||
            !out->close())
            throw SceneError(output + ": cannot write: " + out->geterror());
    });
}

void merge_bands(const std::vector<BandFile>& bands, const std::string& output,
                 const HeaderStrings& attributes) {
    if (bands.empty()) throw SceneError(output + ": no bands to merge");
    MergedImage(bands).write(output, attributes);
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
