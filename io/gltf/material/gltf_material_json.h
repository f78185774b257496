// Internal to io/: reading the JSON objects tinygltf leaves unparsed (material and
// texture extensions) with their glTF defaults, checking types and the ranges the
// extension schemas give: a wrong type throws naming the element and the key, a value
// out of range is clamped with a warning where it can be (out_of_range).
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>

#include "io/gltf/gltf_context.h"

namespace penumbra {

// An inclusive range of allowed values; `open_low` excludes `lo` (attenuationDistance).
struct JsonRange {
    float lo = -FLT_MAX, hi = FLT_MAX;
    bool open_low = false;

    bool contains(float v) const { return (open_low ? v > lo : v >= lo) && v <= hi; }
    std::string text() const {
        if (lo == -FLT_MAX && hi == FLT_MAX) return "the float range";
        std::ostringstream s;
        auto bound = [&](float b) {
            if (std::isinf(b))
                s << (b > 0 ? "+inf" : "-inf");
            else
                s << b;
        };
        s << (open_low ? "(" : "[");
        bound(lo);
        s << ", ";
        bound(hi);
        s << (std::isinf(hi) ? ")" : "]");
        return s.str();
    }
};

inline constexpr JsonRange kUnit{0, 1};
inline constexpr JsonRange kNonNegative{0, INFINITY};
inline constexpr JsonRange kAnyFinite{};

// The extension object `name` in `extensions`, or a null Value when absent. tinygltf
// keeps only extension values that are JSON objects (it drops others unreported).
inline const tinygltf::Value& extension_object(const tinygltf::ExtensionMap& extensions,
                                               const char* name) {
    static const tinygltf::Value none;
    const auto it = extensions.find(name);
    return it == extensions.end() ? none : it->second;
}

// A value outside its schema's range. Where the range is closed on that side, the data
// is renderable: the value is clamped into it with one warning per extension key and
// file (exporters overshoot factors, e.g. a sheen colour of 1.01), and --strict makes it
// the error `problem` naming the element. Values no clamp can mend (attenuationDistance
// 0, beyond float range) are that error always.
inline float out_of_range(const GltfContext& ctx, const std::string& el, const char* key,
                          const std::string& problem, float f, JsonRange range) {
    const bool mendable = std::isfinite(f) && !(range.lo == -FLT_MAX && range.hi == FLT_MAX) &&
                          !(range.open_low && f <= range.lo);
    if (!mendable || ctx.strict) ctx.fail(el, problem + (mendable ? " [--strict]" : ""));
    // The kind: the element without the material's index (extensions.KHR_..., or the
    // core material's own path).
    const size_t dot = el.find("].");
    const std::string kind = dot == std::string::npos ? el : el.substr(dot + 2);
    ctx.warn_once("materials", kind + ": " + key + " values outside " + range.text() +
                                   " are clamped into it");
    return std::clamp(f, range.lo, range.hi);
}

// An optional number of `obj`; throws when it is not a number, clamps (with a warning)
// or throws when it lies outside `range` (out_of_range).
inline float json_number(const GltfContext& ctx, const std::string& el, const tinygltf::Value& obj,
                         const char* key, float fallback, JsonRange range = kAnyFinite) {
    if (!obj.Has(key)) return fallback;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsNumber()) ctx.fail(el, std::string(key) + " is not a number");
    const float f = float(v.GetNumberAsDouble());
    if (!range.contains(f)) {
        std::ostringstream s;
        s << key << " " << v.GetNumberAsDouble() << " is outside " << range.text();
        return out_of_range(ctx, el, key, s.str(), f, range);
    }
    return f;
}

// An optional array of `n` numbers of `obj`, each inside `range`, into out[0..n).
inline void json_numbers(const GltfContext& ctx, const std::string& el, const tinygltf::Value& obj,
                         const char* key, int n, float* out, JsonRange range = kAnyFinite) {
    if (!obj.Has(key)) return;
    const tinygltf::Value& v = obj.Get(key);
    const std::string expected = std::string(key) + " must have " + std::to_string(n) + " numbers";
    if (!v.IsArray() || v.ArrayLen() != size_t(n)) ctx.fail(el, expected);
    for (int k = 0; k < n; ++k) {
        if (!v.Get(k).IsNumber()) ctx.fail(el, expected);
        const float f = float(v.Get(k).GetNumberAsDouble());
        if (!range.contains(f)) {
            std::ostringstream s;
            s << key << "[" << k << "] " << v.Get(k).GetNumberAsDouble() << " is outside "
              << range.text();
            out[k] = out_of_range(ctx, el, key, s.str(), f, range);
            continue;
        }
        out[k] = f;
    }
}

inline Vec2 json_vec2(const GltfContext& ctx, const std::string& el, const tinygltf::Value& obj,
                      const char* key, Vec2 fallback) {
    float v[2] = {fallback.x, fallback.y};
    json_numbers(ctx, el, obj, key, 2, v);
    return {v[0], v[1]};
}

inline Vec3 json_vec3(const GltfContext& ctx, const std::string& el, const tinygltf::Value& obj,
                      const char* key, Vec3 fallback, JsonRange range = kAnyFinite) {
    float v[3] = {fallback.x, fallback.y, fallback.z};
    json_numbers(ctx, el, obj, key, 3, v, range);
    return {v[0], v[1], v[2]};
}

}  // namespace penumbra
