// Assembling an image from row bands rendered apart (`penumbra farm`): each band file is
// a whole-size image whose own rows are rendered; the merge copies those rows, every
// channel (beauty, AOV layers) in the file's own formats, so the result is bit for bit
// the image one machine writes.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace penumbra {

struct BandFile {
    std::string path;
    int row_begin = 0, row_end = 0;  // the rows this file holds
};

// Writes `output` (atomically) with the header, channels and size of the first band and
// rows [row_begin, row_end) of each band from its file; `attributes` replace header
// strings (e.g. the rays summed over bands). EXR or PNG, as the files are. Throws
// SceneError naming the file when a band cannot be read or does not match the first.
void merge_bands(const std::vector<BandFile>& bands, const std::string& output,
                 const std::vector<std::pair<std::string, std::string>>& attributes = {});

// An image file's height in pixels; -1 when it cannot be read.
int image_height(const std::string& path);
// A header string of an image file, or `fallback` when the file or key is missing.
std::string image_attribute(const std::string& path, const std::string& key,
                            const std::string& fallback = "");

}  // namespace penumbra
