// Internal to io/: out-of-spec but renderable mesh data (POSITION accessors without or
// with wrong min/max, index counts that are not whole triangles, primitives without
// triangles), counted while the meshes load and reported as one warning per kind and file.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "core/math/vec.h"
#include "io/gltf/gltf_context.h"

namespace penumbra {

class MeshChecks {
public:
    explicit MeshChecks(const GltfContext& ctx) : m_ctx(ctx) {}

    // POSITION accessor `accessor`, read as `positions`: glTF 2.0 (section 3.6.2.5)
    // requires its min and max, which must bound the data (unless `lossy`: decoded from
    // Draco, whose quantisation moves vertices while encoders keep the original bounds,
    // as chess-board.glb does). Each accessor is checked once.
    void check_position_bounds(int accessor, const std::vector<Vec3>& positions, bool lossy);
    // Primitive `el`'s index list of `count` indices is cut to whole triangles.
    void partial_triangle(const std::string& el, size_t count);
    // Primitive `el` has no triangles and is skipped.
    void no_triangles(const std::string& el);

    // The summary warnings (or, under --strict, the first as an error).
    void report() const;

private:
    const GltfContext& m_ctx;
    std::set<int> m_checked;
    std::vector<std::string> m_unbounded, m_wrong_bounds, m_partial, m_empty;
};

}  // namespace penumbra
