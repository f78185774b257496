// Internal to io/: the JSON pointers of KHR_animation_pointer (RFC 6901 paths into the glTF
// Asset Object Model, e.g. "/materials/0/pbrMetallicRoughness/baseColorFactor"): which
// object and property one names, the property's type, and writing an animated value into
// a copy of that object, so that the loader reads the copy exactly as it reads the file.
#pragma once

#include <tiny_gltf.h>

#include <optional>
#include <string>

namespace penumbra {

enum class PointerObject { Node, Material, Light, Camera };

// A property the renderer reads: the object it belongs to and the pointer's remainder
// inside it ("pbrMetallicRoughness/baseColorFactor", "spot/outerConeAngle", "rotation").
struct PointerTarget {
    PointerObject object = PointerObject::Node;
    int index = -1;
    std::string property;
    size_t width = 1;      // numbers per value: 1 (float, bool) to 4 (float4)
    bool boolean = false;  // KHR_node_visibility's visible: STEP, unsigned byte, 0 is false
};

// Resolves a pointer to a property that changes pixels; empty for pointers to anything
// else (extras, interactivity, mesh default weights, unknown extensions). Indices are
// not range-checked here.
std::optional<PointerTarget> resolve_pointer(const std::string& pointer);

// Writes value[0, target.width) into the copied object's property. Returns false when
// the object does not define the property's enclosing object (KHR_animation_pointer:
// a pointer must name a property present in the asset or defaulted inside an object that
// is), leaving the object unchanged.
bool write_property(tinygltf::Material& m, const std::string& property, const double* value,
                    size_t width);
bool write_property(tinygltf::Light& l, const std::string& property, const double* value,
                    size_t width);
bool write_property(tinygltf::Camera& c, const std::string& property, const double* value,
                    size_t width);

}  // namespace penumbra
