#include "python/py_arrays.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "job/transforms_json.h"

namespace py = pybind11;

namespace penumbra::python {

namespace {

// (H, W, C), or (H, W) for one channel; a copy, so the array owns its pixels.
py::array_t<float> to_array(const Image& image) {
    std::vector<py::ssize_t> shape = {image.height, image.width};
    if (image.channels != 1) shape.push_back(image.channels);
    py::array_t<float> a(shape);
    std::memcpy(a.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(float));
    return a;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

// As transforms.json writes the view: camera to world in OpenGL axes, and the intrinsics.
py::dict camera_dict(const CameraDesc& cam, int width, int height) {
    py::dict d;
    d["name"] = cam.name;
    py::array_t<double> m({4, 4});
    const Mat4 to_world = cam.to_world.matrix();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m.mutable_at(r, c) = to_world(r, c);
    d["transform_matrix"] = m;
    if (cam.type == ProjectionType::Perspective) {
        const Intrinsics in = perspective_intrinsics(width, height, cam.yfov);
        d["yfov"] = cam.yfov;
        d["fl_x"] = in.fl_x;
        d["fl_y"] = in.fl_y;
        d["cx"] = in.cx;
        d["cy"] = in.cy;
    }
    return d;
}

}  // namespace

py::dict to_python(const RenderedImage& image) {
    py::dict out;
    out["rgba"] = to_array(image.rgba);
    for (const ImageLayer& l : image.layers) out[py::str(lower(l.name))] = to_array(l.image);
    out["camera"] = camera_dict(image.camera, image.rgba.width, image.rgba.height);
    out["spp"] = image.spp;
    out["seconds"] = image.seconds;
    return out;
}

}  // namespace penumbra::python
