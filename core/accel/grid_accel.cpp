#include "core/accel/grid_accel.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace penumbra {

void GridAccel::resolution(size_t n, Vec3 extent, int res[3]) {
    const float longest = max_component(extent);
    const float n_longest = 3.0f * std::cbrt(static_cast<float>(std::max<size_t>(n, 1)));
    for (int a = 0; a < 3; ++a) {
        const float r = longest > 0 ? std::round(extent[a] / longest * n_longest) : 1.0f;
        res[a] = static_cast<int>(std::clamp(r, 1.0f, static_cast<float>(kMaxGridRes)));
    }
}

GridAccel::ObjectGrid GridAccel::build_grid(ObjectTriangles triangles) {
    ObjectGrid g;
    g.triangles = std::move(triangles);
    const ObjectTriangles& tris = g.triangles;
    if (tris.size() == 0) return g;
    // Pad the box so that no axis is flat (a quad's grid would have cells of size 0)
    // and points on its faces are safely inside.
    float scale = 0;
    for (int a = 0; a < 3; ++a)
        scale = std::max({scale, std::abs(tris.bounds.lo[a]), std::abs(tris.bounds.hi[a])});
    const float pad =
        std::max({max_component(tris.bounds.diagonal()) * 1e-5f, scale * 0x1p-20f, 1e-30f});
    g.box = tris.bounds;
    g.box.lo -= Vec3(pad);
    g.box.hi += Vec3(pad);
    const Vec3 extent = g.box.diagonal();
    resolution(tris.size(), extent, g.res);
    for (int a = 0; a < 3; ++a) {
        g.cell_size[a] = extent[a] / g.res[a];
        g.inv_cell_size[a] = g.res[a] / extent[a];
    }

    // A triangle goes into every cell its box overlaps, the box grown by 1/1000 of a cell:
    // the walk computes cell boundaries in float, and a hit that rounding puts on the
    // wrong side of a boundary is then still found in the cell being walked.
    auto cell_range = [&](size_t i, int c0[3], int c1[3]) {
        const Bounds3 b = tris.triangle_bounds(i);
        for (int a = 0; a < 3; ++a) {
            const float grow = 1e-3f * g.cell_size[a];
            const float hi = static_cast<float>(g.res[a] - 1);
            c0[a] = int(std::clamp((b.lo[a] - grow - g.box.lo[a]) * g.inv_cell_size[a], 0.0f, hi));
            c1[a] = int(std::clamp((b.hi[a] + grow - g.box.lo[a]) * g.inv_cell_size[a], 0.0f, hi));
        }
    };
    const size_t cells = size_t(g.res[0]) * g.res[1] * g.res[2];
    g.cell_start.assign(cells + 1, 0);
    auto for_each_cell = [&](const int c0[3], const int c1[3], auto&& f) {
        for (int z = c0[2]; z <= c1[2]; ++z)
            for (int y = c0[1]; y <= c1[1]; ++y)
                for (int x = c0[0]; x <= c1[0]; ++x)
                    f(x + size_t(g.res[0]) * (y + size_t(g.res[1]) * z));
    };
    int c0[3], c1[3];
    for (size_t i = 0; i < tris.size(); ++i) {
        cell_range(i, c0, c1);
        for_each_cell(c0, c1, [&](size_t c) { ++g.cell_start[c + 1]; });
    }
    for (size_t c = 0; c < cells; ++c) g.cell_start[c + 1] += g.cell_start[c];
    g.refs.resize(g.cell_start[cells]);
    std::vector<uint32_t> fill(g.cell_start.begin(), g.cell_start.end() - 1);
    for (size_t i = 0; i < tris.size(); ++i) {
        cell_range(i, c0, c1);
        for_each_cell(c0, c1, [&](size_t c) { g.refs[fill[c]++] = static_cast<uint32_t>(i); });
    }
    return g;
}

GridAccel::GridAccel(const Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<Bounds3> object_bounds(scene.objects.size());
    size_t memory = 0;
    m_objects.reserve(scene.objects.size());
    for (size_t oi = 0; oi < scene.objects.size(); ++oi) {
        m_objects.push_back(build_grid(gather_object_triangles(scene, scene.objects[oi])));
        const ObjectGrid& g = m_objects.back();
        object_bounds[oi] = g.triangles.bounds;
        memory += (g.cell_start.capacity() + g.refs.capacity()) * sizeof(uint32_t) +
                  g.triangles.memory_bytes();
    }
    m_instances = InstanceLevel(scene, object_bounds);
    m_stats.name = "grid";
    m_stats.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_stats.object_scenes = m_objects.size();
    m_stats.instances = m_instances.size();
    m_stats.memory_bytes = memory + m_instances.memory_bytes();
}

// 3D-DDA: from the cell where the ray enters the grid, step to the neighbour across
// whichever cell boundary the ray reaches first. A triangle spanning several cells can
// report a hit that lies beyond the current cell; that hit is kept (it shrinks tmax) but
// the walk only ends once the current cell's exit is at or beyond tmax, i.e. once the
// closest hit is known to lie in a cell already walked (the t-range check that replaces
// mailboxing; without mailboxes a triangle may be tested once per cell it overlaps).
template <bool kAnyHit>
bool GridAccel::walk(const ObjectGrid& g, const Ray& ray, float* tmax, Hit* hit) {
    if (g.cell_start.empty()) return false;
    const RayBoxPrecomp rb(ray);
    const float lo[3] = {g.box.lo.x, g.box.lo.y, g.box.lo.z};
    const float hi[3] = {g.box.hi.x, g.box.hi.y, g.box.hi.z};
    float t_enter;
    if (!rb.valid || !ray_box(lo, hi, rb, *tmax, &t_enter)) return false;
    const TrianglePrecomp rt(ray);
    const Vec3 p = ray.o + ray.d * t_enter;
    int cell[3], step[3], out[3];
    float next_t[3];
    // The boundary a cell is left through, as a t: computed from the cell index each
    // time rather than accumulated, so the error does not grow along the walk.
    auto boundary_t = [&](int a) {
        if (step[a] == 0) return std::numeric_limits<float>::infinity();
        const int face = step[a] > 0 ? cell[a] + 1 : cell[a];
        return (g.box.lo[a] + face * g.cell_size[a] - ray.o[a]) * rb.inv_d[a];
    };
    for (int a = 0; a < 3; ++a) {
        const float x = (p[a] - g.box.lo[a]) * g.inv_cell_size[a];
        cell[a] = int(std::clamp(x, 0.0f, float(g.res[a] - 1)));
        step[a] = ray.d[a] > 0 ? 1 : (ray.d[a] < 0 ? -1 : 0);
        out[a] = step[a] > 0 ? g.res[a] : -1;
        next_t[a] = boundary_t(a);
    }
    bool found = false;
    const bool deforms = g.triangles.deforms();
    for (;;) {
        const size_t c = cell[0] + size_t(g.res[0]) * (cell[1] + size_t(g.res[1]) * cell[2]);
        for (uint32_t k = g.cell_start[c]; k < g.cell_start[c + 1]; ++k) {
            const uint32_t i = g.refs[k];
            if (kAnyHit) {
                if (deforms ? g.triangles.any_hit_at(rt, i, 1, ray.tmin, *tmax, ray.time)
                            : g.triangles.any_hit(rt, i, 1, ray.tmin, *tmax))
                    return true;
            } else {
                found |= deforms ? g.triangles.intersect_at(rt, i, 1, ray.tmin, tmax, hit, ray.time)
                                 : g.triangles.intersect(rt, i, 1, ray.tmin, tmax, hit);
            }
        }
        const int a = next_t[0] < next_t[1] ? (next_t[0] < next_t[2] ? 0 : 2)
                                            : (next_t[1] < next_t[2] ? 1 : 2);
        if (*tmax <= next_t[a]) break;
        cell[a] += step[a];
        if (cell[a] == out[a]) break;
        next_t[a] = boundary_t(a);
    }
    return found;
}

std::optional<Hit> GridAccel::do_intersect(const Ray& ray) const {
    Hit best;
    bool found = false;
    float tmax = ray.tmax;
    m_instances.traverse(
        ray, tmax, [&](uint32_t instance, uint32_t object, const Ray& oray, float& t_closest) {
            Hit h;
            if (walk<false>(m_objects[object], oray, &t_closest, &h)) {
                best = h;
                best.instance = instance;
                found = true;
            }
            return false;
        });
    if (!found) return std::nullopt;
    return best;
}

bool GridAccel::do_occluded(const Ray& ray) const {
    float tmax = ray.tmax;
    bool hit = false;
    m_instances.traverse(ray, tmax, [&](uint32_t, uint32_t object, const Ray& oray, float& t) {
        float tt = t;
        hit = walk<true>(m_objects[object], oray, &tt, nullptr);
        return hit;
    });
    return hit;
}

}  // namespace penumbra
