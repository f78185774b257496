// Assembling an image from row bands rendered apart (`penumbra farm`): each band file is
// a whole-size image whose own rows are rendered; the merge copies those rows, every
// channel (beauty, AOV layers) in the file's own formats, so the result is bit for bit
// the image one machine writes.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"

namespace penumbra {

struct BandFile {
    std::string path;
    int row_begin = 0, row_end = 0;  // the rows this file holds
};

using HeaderStrings = std::vector<std::pair<std::string, std::string>>;

// An image assembled from its bands in memory: the first band's header, channels, channel
// formats and size, and rows [row_begin, row_end) of each band from its file. It can be
// edited before it is written: the merge of a render that denoises replaces the colour,
// adds a layer and leaves out the denoiser's input (apps/penumbra/farm/farm_merge.cpp).
class MergedImage {
public:
    // Throws SceneError naming the file when a band cannot be read or does not match the
    // first.
    explicit MergedImage(const std::vector<BandFile>& bands);
    ~MergedImage();
    MergedImage(const MergedImage&) = delete;
    MergedImage& operator=(const MergedImage&) = delete;
    int width() const;
    int height() const;
    // The channels of these names, in that order, as one float image (half values are
    // exact in float). Throws SceneError naming the first band's file when a channel is
    // missing or the image is 8-bit.
    Image channels(const std::vector<std::string>& names) const;
    // Overwrites the named channels with values' channels (one each, in that order); the
    // write stores them in the channels' own formats.
    void set_channels(const std::vector<std::string>& names, const Image& values);
    // Adds channels with values' channels right after the channel `after`, each stored in
    // the format of the channel `like` (half or float).
    void insert_channels(const std::string& after, const std::vector<std::string>& names,
                         const std::string& like, const Image& values);
    // Leaves out every channel whose name starts with prefix.
    void remove_channels(const std::string& prefix);
    // Writes `output` (atomically; EXR or PNG, as the bands are) with `attributes`
    // replacing header strings.
    void write(const std::string& output, const HeaderStrings& attributes = {}) const;

private:
    struct Data;
    std::unique_ptr<Data> m_data;
};

// Writes `output` (atomically) with the header, channels and size of the first band and
// rows [row_begin, row_end) of each band from its file; `attributes` replace header
// strings (e.g. the rays summed over bands). EXR or PNG, as the files are. Throws
// SceneError naming the file when a band cannot be read or does not match the first.
void merge_bands(const std::vector<BandFile>& bands, const std::string& output,
                 const HeaderStrings& attributes = {});

// An image file's height in pixels; -1 when it cannot be read.
int image_height(const std::string& path);
// A header string of an image file, or `fallback` when the file or key is missing.
std::string image_attribute(const std::string& path, const std::string& key,
                            const std::string& fallback = "");

}  // namespace penumbra
