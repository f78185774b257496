// A small glTF file whose every kind of animated value has a known answer, for the
// KHR_animation_pointer and KHR_node_visibility tests (load values and rendered pixels).
#pragma once

#include <string>

#include "support/gltf_builder.h"

namespace penumbra::test {

// A unit quad at z = 0 (material 0, unlit, base colour LINEAR from red at 0 s to blue at
// 1 s) and, in front of its left half, a green unlit quad (node 1) whose visibility is
// STEP: shown from 0 s, hidden from 0.5 s. A point light (node 2) whose intensity goes
// LINEAR from 10 to 30 cd, and a perspective camera (node 3) whose yfov goes from 0.5 to
// 1.0 rad, both over [0, 1] s.
inline std::string animated_scene(const ScratchDir& dir) {
    GltfBuilder b;
    const int back = b.add<float>({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, kFloat, "VEC3");
    const int front = b.add<float>({-1, -1, 0.5f, 0, -1, 0.5f, 0, 1, 0.5f, -1, 1, 0.5f},
                                   kFloat, "VEC3");
    const int idx = b.add<uint16_t>({0, 1, 2, 0, 2, 3}, kUShort, "SCALAR");
    const int times = b.add<float>({0, 1}, kFloat, "SCALAR");
    const int colors = b.add<float>({1, 0, 0, 1, 0, 0, 1, 1}, kFloat, "VEC4");
    const int vis_times = b.add<float>({0, 0.5f}, kFloat, "SCALAR");
    const int vis = b.add<uint8_t>({1, 0}, kUByte, "SCALAR");
    const int intensity = b.add<float>({10, 30}, kFloat, "SCALAR");
    const int yfov = b.add<float>({0.5f, 1.0f}, kFloat, "SCALAR");
    auto sampler = [](int in, int out, const char* interp) {
        return "{\"input\":" + std::to_string(in) + ",\"output\":" + std::to_string(out) +
               ",\"interpolation\":\"" + interp + "\"}";
    };
    auto channel = [](int s, const std::string& pointer) {
        return "{\"sampler\":" + std::to_string(s) +
               ",\"target\":{\"path\":\"pointer\",\"extensions\":{\"KHR_animation_pointer\":"
               "{\"pointer\":\"" + pointer + "\"}}}}";
    };
    auto mesh = [&](int pos, int material) {
        return "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
               "},\"indices\":" + std::to_string(idx) + ",\"material\":" +
               std::to_string(material) + "}]}";
    };
    const std::string unlit = "\"extensions\":{\"KHR_materials_unlit\":{}}";
    const std::string members =
        "\"extensionsUsed\":[\"KHR_animation_pointer\",\"KHR_node_visibility\","
        "\"KHR_materials_unlit\",\"KHR_lights_punctual\"],"
        "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\","
        "\"intensity\":10}]}},"
        "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1]}," + unlit +
        "},{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,1,0,1]}," + unlit + "}],"
        "\"meshes\":[" + mesh(back, 0) + "," + mesh(front, 1) + "],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,\"znear\":0.1}}],"
        "\"nodes\":[{\"mesh\":0},{\"mesh\":1,\"extensions\":{\"KHR_node_visibility\":"
        "{\"visible\":true}}},{\"translation\":[0,0,2],\"extensions\":{\"KHR_lights_punctual\":"
        "{\"light\":0}}},{\"camera\":0,\"translation\":[0,0,5]}],"
        "\"scenes\":[{\"nodes\":[0,1,2,3]}],"
        "\"animations\":[{\"samplers\":[" +
        sampler(times, colors, "LINEAR") + "," + sampler(vis_times, vis, "STEP") + "," +
        sampler(times, intensity, "LINEAR") + "," + sampler(times, yfov, "LINEAR") +
        "],\"channels\":[" + channel(0, "/materials/0/pbrMetallicRoughness/baseColorFactor") +
        "," + channel(1, "/nodes/1/extensions/KHR_node_visibility/visible") + "," +
        channel(2, "/extensions/KHR_lights_punctual/lights/0/intensity") + "," +
        channel(3, "/cameras/0/perspective/yfov") + "]}]";
    return b.write(dir, "animated.gltf", members, BufferStorage::DataUri);
}

}  // namespace penumbra::test
