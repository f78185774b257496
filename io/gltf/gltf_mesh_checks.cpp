#include "io/gltf/gltf_mesh_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace penumbra {

namespace {

// An accessor's min or max as a float position component: normalized integer accessors
// state theirs in the raw integers (glTF 2.0, section 3.6.2.5), which map as their data
// do (section 3.11).
float bound_value(double raw, const tinygltf::Accessor& a) {
    if (!a.normalized) return float(raw);
    switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return std::max(float(raw / 127.0), -1.0f);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return float(raw / 255.0);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return std::max(float(raw / 32767.0), -1.0f);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return float(raw / 65535.0);
        default:
            return float(raw);
    }
}

std::string format(Vec3 v) {
    char s[96];
    std::snprintf(s, sizeof(s), "[%g, %g, %g]", v.x, v.y, v.z);
    return s;
}

}  // namespace

void MeshChecks::check_position_bounds(int accessor, const std::vector<Vec3>& positions,
                                       bool lossy) {
    if (positions.empty() || !m_checked.insert(accessor).second) return;
    const tinygltf::Accessor& a = m_ctx.model.accessors[size_t(accessor)];
    const std::string el = element("accessors", size_t(accessor));
    // A min or max of the wrong length is as good as none.
    if (a.minValues.size() != 3 || a.maxValues.size() != 3) {
        m_unbounded.push_back(el);
        return;
    }
    if (lossy) return;
    Vec3 lo = positions[0], hi = positions[0];
    for (const Vec3& p : positions) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    const Vec3 file_lo(bound_value(a.minValues[0], a), bound_value(a.minValues[1], a),
                       bound_value(a.minValues[2], a));
    const Vec3 file_hi(bound_value(a.maxValues[0], a), bound_value(a.maxValues[1], a),
                       bound_value(a.maxValues[2], a));
    // Exporters print min/max in decimal, often to 6 or 7 digits: allow 1e-4 of the
    // accessor's size (or of the coordinates, far from the origin), which still sees a
    // bound that is off by a vertex's spacing in all but the densest meshes.
    float scale = max_component(hi - lo);
    for (int c = 0; c < 3; ++c) scale = std::max({scale, std::abs(lo[c]), std::abs(hi[c])});
    const float tolerance = 1e-4f * scale;
    bool agree = true;
    for (int c = 0; c < 3; ++c)
        agree = agree && std::abs(file_lo[c] - lo[c]) <= tolerance &&
                std::abs(file_hi[c] - hi[c]) <= tolerance;
    if (!agree)
        m_wrong_bounds.push_back(el + " min " + format(file_lo) + " max " + format(file_hi) +
                                 ", data " + format(lo) + " to " + format(hi));
}

void MeshChecks::partial_triangle(const std::string& el, size_t count) {
    m_partial.push_back(el + " has " + std::to_string(count));
}

void MeshChecks::no_triangles(const std::string& el) { m_empty.push_back(el); }

void MeshChecks::report() const {
    if (!m_unbounded.empty())
        m_ctx.warn("accessors", std::to_string(m_unbounded.size()) +
                                    " POSITION accessor(s) have no min/max (glTF requires "
                                    "them); bounds computed from the data" +
                                    examples(m_unbounded));
    if (!m_wrong_bounds.empty())
        m_ctx.warn("accessors", std::to_string(m_wrong_bounds.size()) +
                                    " POSITION accessor(s) have a min/max that disagrees with "
                                    "their data; bounds computed from the data" +
                                    examples(m_wrong_bounds));
    if (!m_partial.empty())
        m_ctx.warn("meshes", std::to_string(m_partial.size()) +
                                 " primitive(s) have an index count that is not a multiple of "
                                 "3; the last 1 or 2 indices are ignored" +
                                 examples(m_partial));
    if (!m_empty.empty())
        m_ctx.warn("meshes", std::to_string(m_empty.size()) +
                                 " primitive(s) have no triangles; skipped" + examples(m_empty));
}

}  // namespace penumbra
