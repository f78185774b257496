#include "job/render_output.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace penumbra {

namespace {

std::string file_name_safe(const std::string& s, const char* if_empty) {
    if (s.empty()) return if_empty;
    std::string out = s;
    for (char& c : out)
        if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20) c = '_';
    return out;
}

}  // namespace

std::string expand_output_name(const std::string& pattern, const OutputNameFields& f) {
    std::string out;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '{') {
            out += pattern[i];
            continue;
        }
        const size_t close = pattern.find('}', i);
        if (close == std::string::npos)
            throw std::invalid_argument("name '" + pattern + "': unclosed '{'");
        const std::string key = pattern.substr(i + 1, close - i - 1);
        if (key == "scene") {
            out += file_name_safe(f.scene, "scene");
        } else if (key == "camera") {
            out += file_name_safe(f.camera, "camera");
        } else if (key == "frame") {
            char buf[16];
            std::snprintf(buf, sizeof buf, "%04d", f.frame);
            out += buf;
        } else if (key == "view") {
            char buf[16];
            std::snprintf(buf, sizeof buf, "%04d", f.view);
            out += buf;
        } else if (key == "index") {
            out += std::to_string(f.index);
        } else {
            throw std::invalid_argument("name '" + pattern + "': unknown placeholder {" + key +
                                        "} (expected {scene}, {camera}, {frame}, {view}, {index})");
        }
        i = close;
    }
    return out;
}

bool uses_placeholder(const std::string& pattern, const std::string& name) {
    return pattern.find("{" + name + "}") != std::string::npos;
}

bool is_finished_render(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        OIIO::geterror();  // clear OIIO's per-thread error so it is not reported later
        return false;
    }
    const bool partial = in->spec().get_string_attribute("penumbra:partial") == "1";
    in->close();
    return !partial;
}

}  // namespace penumbra
