#include "io/gltf/animation/gltf_pointer_channels.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"

namespace penumbra {

namespace {

// The GLB's JSON chunk (glTF 2.0, section 4.4), bounds-checked.
std::string glb_json(const std::string& glb, const std::string& path) {
    auto u32 = [&](size_t at) {
        uint32_t v = 0;
        std::memcpy(&v, glb.data() + at, 4);
        return v;
    };
    if (glb.size() < 20 || u32(16) != 0x4E4F534A || u32(12) > glb.size() - 20)
        throw SceneError(path + ": GLB JSON chunk is malformed");
    return glb.substr(20, u32(12));
}

// tinygltf's lines about a channel target without a node, which pointer channels are.
std::string without_node_reports(const std::string& text) {
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line))
        if (line.find("'node' property is missing") == std::string::npos &&
            line.find("`node` field is missing in animation.channels.target") == std::string::npos)
            out += line + "\n";
    return out;
}

tinygltf::AnimationChannel read_channel(const nlohmann::json& c) {
    tinygltf::AnimationChannel ch;
    if (c.contains("sampler") && c["sampler"].is_number_integer()) ch.sampler = c["sampler"].get<int>();
    if (!c.contains("target") || !c["target"].is_object()) return ch;
    const nlohmann::json& t = c["target"];
    if (t.contains("node") && t["node"].is_number_integer()) ch.target_node = t["node"].get<int>();
    if (t.contains("path") && t["path"].is_string()) ch.target_path = t["path"].get<std::string>();
    const auto ext = t.find("extensions");
    if (ext != t.end() && ext->is_object() && ext->contains("KHR_animation_pointer")) {
        const nlohmann::json& p = (*ext)["KHR_animation_pointer"];
        tinygltf::Value::Object obj;
        if (p.is_object() && p.contains("pointer") && p["pointer"].is_string())
            obj["pointer"] = tinygltf::Value(p["pointer"].get<std::string>());
        ch.target_extensions["KHR_animation_pointer"] = tinygltf::Value(std::move(obj));
    }
    return ch;
}

}  // namespace

void restore_pointer_channels(tinygltf::Model& model, const std::string& bytes, bool binary,
                              const std::string& path, std::string& warn, std::string& err) {
    const auto& used = model.extensionsUsed;
    if (std::find(used.begin(), used.end(), "KHR_animation_pointer") == used.end()) return;
    const nlohmann::json doc =
        nlohmann::json::parse(binary ? glb_json(bytes, path) : bytes, nullptr, false);
    const auto anims = doc.is_object() ? doc.find("animations") : doc.end();
    if (anims == doc.end() || !anims->is_array() || anims->size() != model.animations.size())
        throw SceneError(path + ": animations: the JSON does not match the parsed file");
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const nlohmann::json& channels = (*anims)[a].value("channels", nlohmann::json::array());
        if (!channels.is_array()) continue;
        std::vector<tinygltf::AnimationChannel> restored;
        for (const nlohmann::json& c : channels) restored.push_back(read_channel(c));
        model.animations[a].channels = std::move(restored);
    }
    warn = without_node_reports(warn);
    err = without_node_reports(err);
}

}  // namespace penumbra
