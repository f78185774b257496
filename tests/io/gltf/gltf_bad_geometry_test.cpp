// scenes/hard/bad-geometry.gltf: what the loader keeps and how it renders. Degenerate
// triangles and duplicate vertices are kept (never hit, harmless); a zero-length normal
// falls back to the geometric normal; a mirrored instance keeps outward normals; normals
// of a non-uniformly scaled instance follow the inverse transpose. Non-finite positions,
// normals and tangents are rejected (scenes/invalid/, docs/conventions.md).
#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/embree_accel.h"
#include "core/camera/orthographic_camera.h"
#include "core/surface_point.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/render_scene.h"

namespace penumbra {
namespace {

enum { kBad = 0, kMirrored = 1, kSquashed = 2 };  // instances, in node order

TEST(GltfBadGeometry, DegenerateTrianglesAndZeroNormalsAreKeptAndRenderFinite) {
    const Scene scene = load_gltf(test::source_path("scenes/hard/bad-geometry.gltf"));
    ASSERT_EQ(scene.instances.size(), 3u);
    const TriangleMesh& bad = scene.meshes[scene.objects[scene.instances[kBad].object].meshes[0]];
    EXPECT_EQ(bad.indices.size(), 12u);  // all four triangles, the degenerate two included
    const OrthographicCamera camera(Transform::look_at({0, 3, 0.5f}, {0, 0, 0.5f}, {0, 0, -1}),
                                    2.5f, 2.5f, 48, 48);
    for (const char* integrator : {"basic", "path"}) {
        const test::SceneRender r = test::render_scene(scene, camera, integrator, 4);
        EXPECT_EQ(r.nonfinite_samples, 0u) << integrator;
        for (float v : r.image.pixels) ASSERT_TRUE(std::isfinite(v)) << integrator;
    }
    // Right at the vertex with the zero normal (vertex 2 of triangle 0) the shading
    // normal is the geometric one, not NaN.
    Hit hit;
    hit.instance = kBad;
    hit.mesh = scene.objects[scene.instances[kBad].object].meshes[0];
    hit.prim = 0;
    hit.b1 = 0;
    hit.b2 = 1;
    Ray ray;
    ray.d = {0, -1, 0};
    const SurfacePoint sp = make_surface_point(scene, ray, hit);
    EXPECT_EQ(sp.ns.y, 1.0f);
    EXPECT_EQ(sp.ng.y, 1.0f);
    EXPECT_TRUE(std::isfinite(sp.p_smooth.x) && std::isfinite(sp.p_smooth.y));
}

// Rays from all around towards the centre of a sphere instance: the hit's geometric and
// shading normals face back to the ray's origin (outward).
int inward_normals(const Scene& scene, const Accel& accel, int instance, Vec3 centre) {
    int wrong = 0;
    for (int i = 0; i < 200; ++i) {
        const float z = 1 - 2 * (i + 0.5f) / 200, phi = 2.39996f * i;
        const float r = std::sqrt(1 - z * z);
        const Vec3 dir(r * std::cos(phi), z, r * std::sin(phi));
        Ray ray;
        ray.o = centre + dir * 3;
        ray.d = -dir;
        const std::optional<Hit> hit = accel.intersect(ray);
        if (!hit || hit->instance != uint32_t(instance)) continue;
        const SurfacePoint sp = make_surface_point(scene, ray, *hit);
        if (dot(sp.ng, dir) <= 0 || dot(sp.ns, dir) <= 0) ++wrong;
    }
    return wrong;
}

TEST(GltfBadGeometry, MirroredInstanceKeepsOutwardNormals) {
    const Scene scene = load_gltf(test::source_path("scenes/hard/bad-geometry.gltf"));
    const EmbreeAccel accel(scene);
    ASSERT_TRUE(scene.instances[kMirrored].to_world.swaps_handedness());
    EXPECT_EQ(inward_normals(scene, accel, kMirrored, {0, 1, 0}), 0);
    EXPECT_EQ(inward_normals(scene, accel, kSquashed, {0, 1, 2}), 0);
}

TEST(GltfBadGeometry, NonUniformScaleTransformsNormalsByTheInverseTranspose) {
    const Scene scene = load_gltf(test::source_path("scenes/hard/bad-geometry.gltf"));
    const Instance& inst = scene.instances[kSquashed];
    const uint32_t mesh_index = scene.objects[inst.object].meshes[0];
    const TriangleMesh& mesh = scene.meshes[mesh_index];
    const Vec3 s(2.0f, 0.25f, 1.0f);  // the node's scale
    for (uint32_t prim = 0; prim < mesh.indices.size() / 3; prim += 7) {
        Hit hit;
        hit.instance = kSquashed;
        hit.mesh = mesh_index;
        hit.prim = prim;
        hit.b1 = hit.b2 = 0;  // at vertex 0 of the triangle
        Ray ray;
        ray.d = {0, 0, -1};
        const SurfacePoint sp = make_surface_point(scene, ray, hit);
        const Vec3 n = mesh.normals[mesh.indices[3 * prim]];
        const Vec3 expected = normalize(Vec3(n.x / s.x, n.y / s.y, n.z / s.z));
        EXPECT_NEAR(sp.ns.x, expected.x, 1e-4f) << prim;
        EXPECT_NEAR(sp.ns.y, expected.y, 1e-4f) << prim;
        EXPECT_NEAR(sp.ns.z, expected.z, 1e-4f) << prim;
        // The geometric normal is perpendicular to the world-space triangle's edges.
        const Vec3 p0 = inst.to_world.point(mesh.positions[mesh.indices[3 * prim]]);
        const Vec3 p1 = inst.to_world.point(mesh.positions[mesh.indices[3 * prim + 1]]);
        const Vec3 p2 = inst.to_world.point(mesh.positions[mesh.indices[3 * prim + 2]]);
        EXPECT_NEAR(dot(sp.ng, normalize(p1 - p0)), 0.0f, 1e-4f) << prim;
        EXPECT_NEAR(dot(sp.ng, normalize(p2 - p0)), 0.0f, 1e-4f) << prim;
    }
}

}  // namespace
}  // namespace penumbra
