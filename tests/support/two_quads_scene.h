// A glTF file with known coverage, for end-to-end tests of alpha and ID layers: an
// orthographic camera over 8 x 8 world units (at 16 x 16 pixels, 2 pixels a unit), quad
// "left" (node 1, material 0 "grey") over columns 0-5 and quad "right" (node 2, glTF's
// default material) over columns 6-11, both over rows 4-15; the rest is background.
#pragma once

#include <string>

#include "support/gltf_builder.h"

namespace penumbra::test {

inline std::string write_two_quads(const ScratchDir& dir) {
    GltfBuilder b;
    // World x from -4 to -1 (left) and -1 to 2 (right), y from -4 to 2, at z = 0, facing +z.
    auto quad = [&](float x0, float x1) {
        const int pos = b.add<float>({x0, -4, 0, x1, -4, 0, x1, 2, 0, x0, 2, 0}, kFloat, "VEC3");
        const int idx = b.add<uint16_t>({0, 1, 2, 0, 2, 3}, kUShort, "SCALAR");
        return "{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
               "},\"indices\":" + std::to_string(idx);
    };
    const std::string left = quad(-4, -1) + ",\"material\":0}", right = quad(-1, 2) + "}";
    const std::string members =
        "\"materials\":[{\"name\":\"grey\",\"pbrMetallicRoughness\":{\"baseColorFactor\":"
        "[0.5,0.5,0.5,1],\"metallicFactor\":0}}],"
        "\"meshes\":[{\"primitives\":[" +
        left + "]},{\"primitives\":[" + right +
        "]}],"
        "\"cameras\":[{\"type\":\"orthographic\",\"orthographic\":{\"xmag\":4,\"ymag\":4,"
        "\"znear\":0.1,\"zfar\":100}}],"
        "\"nodes\":[{\"camera\":0,\"translation\":[0,0,5]},{\"name\":\"left\",\"mesh\":0},"
        "{\"name\":\"right\",\"mesh\":1}],"
        "\"scenes\":[{\"nodes\":[0,1,2]}],\"scene\":0";
    return b.write(dir, "quads.gltf", members, BufferStorage::DataUri);
}

// Where the file's geometry is, at 16 x 16 pixels.
inline bool two_quads_miss(int x, int y) { return y < 4 || x >= 12; }
inline bool two_quads_left(int x, int y) { return !two_quads_miss(x, y) && x < 6; }

}  // namespace penumbra::test
