// Where a batch writes each image: output name templates with {scene}, {camera},
// {frame}, {view} and {index}; and whether an existing output is a finished render (a readable
// image not marked partial), which is what lets an interrupted batch resume.
#pragma once

#include <cstddef>
#include <string>

namespace penumbra {

struct OutputNameFields {
    std::string scene;   // the scene file's stem
    std::string camera;  // the camera's name
    int frame = 0;       // written as at least 4 digits: 0007
    size_t index = 0;    // the image's position in the batch, from 0
    int view = 0;        // the view's index (--views), as at least 4 digits
};

// Replaces each placeholder; characters that are not safe in a file name ('/', '\\',
// control characters) in the scene or camera name become '_'. Throws
// std::invalid_argument for an unknown placeholder or an unclosed '{'.
std::string expand_output_name(const std::string& pattern, const OutputNameFields& fields);
bool uses_placeholder(const std::string& pattern, const std::string& name);  // "camera"

// True when path holds an image OpenImageIO can open whose "penumbra:partial" attribute
// is not "1". A missing, truncated or foreign file is not finished.
bool is_finished_render(const std::string& path);

}  // namespace penumbra
