// Internal to io/: reading glTF accessors into flat arrays. Handles byteOffset and
// byteStride, normalized integers, sparse substitution and accessors without a
// bufferView (zeros), and checks every byte range against its bufferView and buffer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/gltf/gltf_context.h"

namespace penumbra {

// The accessor `index`, referenced from `user` (an element path) as `semantic`
// ("POSITION", "indices"); throws when the index is out of range.
const tinygltf::Accessor& get_accessor(const GltfContext& ctx, const std::string& user,
                                       const std::string& semantic, int index);

// All elements as floats, component_count(type) per element. Normalized integers map to
// [0, 1] or [-1, 1] (glTF 2.0, section 3.11); other integers convert by value.
std::vector<float> read_floats(const GltfContext& ctx, int index);

// All elements of an unsigned-integer SCALAR accessor (indices), by value.
std::vector<uint32_t> read_uints(const GltfContext& ctx, int index);

// The bytes of bufferView `view` (e.g. an image's), referenced from `user`, after
// checking the index and that the view lies inside its buffer.
std::vector<uint8_t> buffer_view_bytes(const GltfContext& ctx, const std::string& user, int view);

// 1 for SCALAR, 2-4 for VECn, 4/9/16 for MATn; 0 for anything else.
int component_count(int type);
// Bytes per component; 0 for a component type glTF does not define.
int component_size(int component_type);
// "VEC3 of unsigned short (normalized)", for messages.
std::string describe_accessor(const tinygltf::Accessor& a);

}  // namespace penumbra
