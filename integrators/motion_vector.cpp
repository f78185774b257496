#include "integrators/motion_vector.h"

#include <cmath>

#include "core/camera/camera_matrices.h"

namespace penumbra {

namespace {

// Penumbra's NDC (y down, [0, 1]^2) to Cycles' raster (y up, pixels).
Mat4 ndc_to_raster(int width, int height) {
    Mat4 m = Mat4::identity();
    m(0, 0) = float(width);
    m(1, 1) = -float(height);
    m(1, 3) = float(height);
    return m;
}

// The point through a world-to-raster matrix (homogeneous); w = 0 (a point in the
// camera's plane) gives a non-finite result.
Vec2 raster(const Mat4& m, Vec3 p) {
    const float x = m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.z + m(0, 3);
    const float y = m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.z + m(1, 3);
    const float w = m(3, 0) * p.x + m(3, 1) * p.y + m(3, 2) * p.z + m(3, 3);
    return {x / w, y / w};
}

Vec3 affine(const Mat4& m, Vec3 p) {
    return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.z + m(0, 3),
            m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.z + m(1, 3),
            m(2, 0) * p.x + m(2, 1) * p.y + m(2, 2) * p.z + m(2, 3)};
}

// The hit's barycentric mix of the triangle's vertices in `positions` (object space).
Vec3 object_point(const std::vector<Vec3>& positions, const TriangleMesh& mesh, const Hit& hit) {
    const uint32_t* idx = &mesh.indices[size_t(hit.prim) * 3];
    const float b0 = 1 - hit.b1 - hit.b2;
    return positions[idx[0]] * b0 + positions[idx[1]] * hit.b1 + positions[idx[2]] * hit.b2;
}

// The hit's world point in a neighbouring frame (NeighbourFrame: what does not move there
// is left out of it).
Vec3 neighbour_point(const Scene& scene, const NeighbourFrame& f, const TriangleMesh& mesh,
                     const Hit& hit) {
    const bool deformed = hit.mesh < f.positions.size() && !f.positions[hit.mesh].empty();
    const Mat4& to_world = f.instances.empty() ? scene.instances[hit.instance].to_world.matrix()
                                               : f.instances[hit.instance];
    return affine(to_world,
                  object_point(deformed ? f.positions[hit.mesh] : mesh.positions, mesh, hit));
}

}  // namespace

MotionVectorCameras motion_vector_cameras(const CameraDesc& camera, const CameraDesc* previous,
                                          const CameraDesc* next, int width, int height) {
    const Mat4 to_raster = ndc_to_raster(width, height);
    MotionVectorCameras c;
    c.current = to_raster * world_to_ndc(camera, width, height);
    c.previous = previous ? to_raster * world_to_ndc(*previous, width, height) : c.current;
    c.next = next ? to_raster * world_to_ndc(*next, width, height) : c.current;
    return c;
}

Vec4 motion_vector(const Scene& scene, const MotionVectorCameras& cameras, const Hit& hit) {
    if (!scene.frame_neighbours) return {};
    const TriangleMesh& mesh = scene.meshes[hit.mesh];
    const FrameNeighbours& n = *scene.frame_neighbours;
    const Vec3 p = affine(scene.instances[hit.instance].to_world.matrix(),
                          object_point(mesh.positions, mesh, hit));
    const Vec2 at = raster(cameras.current, p);
    const Vec2 before = raster(cameras.previous, neighbour_point(scene, n.previous, mesh, hit));
    const Vec2 after = raster(cameras.next, neighbour_point(scene, n.next, mesh, hit));
    const Vec4 v(before.x - at.x, before.y - at.y, at.x - after.x, at.y - after.y);
    return std::isfinite(v.x + v.y + v.z + v.w) ? v : Vec4{};
}

}  // namespace penumbra
