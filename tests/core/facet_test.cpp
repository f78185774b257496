// Precomputed facets (core/facet.*): a hit that carries its triangle's facet gives the
// surface point a hit without one gives, bit for bit, on flat, smooth, unshaded and
// degenerate triangles under translations, rotations, non-uniform scales and mirrors, with
// and without UVs (the bare facets' own path); a flat facet's shading normal is its
// geometric normal, on the vertex normals' side.
#include "core/facet.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/surface_point.h"
#include "support/scene_builder.h"
#include "support/surface_point_checks.h"

namespace penumbra {
namespace {

struct Case {
    std::string name;
    std::vector<Vec3> positions, normals;
    uint32_t expected_flags;  // with a UV set
    bool bare_without_uvs;    // Facet::kBare is added where the mesh has no UVs
};

std::vector<Case> cases() {
    const std::vector<Vec3> tri = {{0, 0, 0}, {1, 0.3f, 0}, {0.2f, 0.1f, 1}};
    const Vec3 face = normalize(cross(tri[1] - tri[0], tri[2] - tri[0]));
    const Vec3 up(0, 1, 0);
    constexpr uint32_t kN = Facet::kNormal, kF = Facet::kFlat, kO = Facet::kOpposed;
    return {
        {"flat", tri, {face, face, face}, kN | kF, true},
        {"flat, normals against the winding", tri, {-face, -face, -face}, kN | kF | kO, true},
        {"equal normals off the face normal", tri, {up, up, up}, kN, false},
        {"smooth", tri, {up, face, normalize(Vec3(0.2f, 1, 0.3f))}, kN, false},
        {"no normals", tri, {}, kN, true},
        // Coordinates of both signs and sizes: the bare path's SSE lanes take |p| apart.
        {"no normals, negative coordinates",
         {{-3.5f, 0.25f, -1e3f}, {2, -0.3f, -999.5f}, {-0.2f, -7, -1000.25f}},
         {},
         kN,
         true},
        {"huge normals (norms overflow)",
         tri,
         {face * 1e20f, face * 1e20f, face * 1e20f},
         kN,
         false},
        // No normal; flat, as the per-hit test has always judged a zero face normal.
        {"degenerate", {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {up, up, up}, kF, false},
    };
}

TEST(Facet, HitsWithTheirFacetGiveTheSurfacePointOfHitsWithout) {
    const float s = std::sqrt(0.5f);
    const std::vector<std::pair<std::string, Transform>> transforms = {
        {"identity", Transform()},
        {"translation", Transform::translate({1, -2, 3})},
        {"rotation and scale", Transform::trs({0.5f, 0, 0}, Quat{0, s, 0, s}, {2, 1, 0.5f})},
        {"mirror", Transform::scale({1, 1, -1}) *
                       Transform::trs({0, 4, 0}, Quat{0.38f, 0, 0, 0.92f}, {1, 3, 1})},
    };
    const float bary[][2] = {{0.3f, 0.5f}, {0, 0}, {1, 0}, {0.1f, 0.1f}};
    const Vec3 dirs[] = {{0, -1, 0}, {0.3f, 0.5f, -0.8f}, {-2, 0.1f, 3}};
    int compared = 0;
    for (const Case& c : cases())
        for (const auto& [xf_name, xf] : transforms)
            for (const bool uvs : {true, false}) {
                Scene scene;
                TriangleMesh mesh;
                mesh.positions = c.positions;
                mesh.normals = c.normals;
                if (uvs) mesh.uv0 = {{0, 0}, {1, 0}, {0.3f, 0.8f}};  // dp/du, the cone's UV widths
                mesh.indices = {0, 1, 2};
                test::add_instance(scene, test::add_mesh_object(scene, mesh, "triangle"), xf);
                const Facet facet = make_facet(scene.meshes[0], xf, 0);
                const uint32_t expected =
                    c.expected_flags | (!uvs && c.bare_without_uvs ? Facet::kBare : 0);
                EXPECT_EQ(facet.flags, expected) << c.name << ", " << xf_name << ", uvs " << uvs;
                for (const auto& b : bary)
                    for (const Vec3& d : dirs)
                        for (const bool cone : {false, true}) {
                            Ray ray;
                            ray.d = d;
                            if (cone) ray.cone = {0.01f, 0.002f};
                            Hit hit;
                            hit.t = 1.5f;
                            hit.b1 = b[0];
                            hit.b2 = b[1];
                            const SurfacePoint computed = make_surface_point(scene, ray, hit);
                            hit.facet = &facet;
                            const SurfacePoint looked_up = make_surface_point(scene, ray, hit);
                            test::expect_same_surface_point(looked_up, computed,
                                                            c.name + ", " + xf_name + ", b " +
                                                                std::to_string(b[0]) + " " +
                                                                std::to_string(b[1]));
                            if ((facet.flags & Facet::kFlat) && (facet.flags & Facet::kNormal)) {
                                // A flat facet shades with its geometric normal, which is the
                                // vertex normal's direction to within 1e-6 radians.
                                EXPECT_EQ(computed.ns, computed.ng) << c.name << ", " << xf_name;
                                const Vec3 n0 = normalize(xf.normal(c.normals[0]));
                                EXPECT_GT(dot(computed.ns, n0), 1 - 1e-6f)
                                    << c.name << ", " << xf_name;
                            }
                            ++compared;
                        }
            }
    EXPECT_EQ(compared, 8 * 4 * 2 * 4 * 3 * 2);
}

// A bare facet (make_surface_point's short path) is one whose hits need nothing of the mesh
// but positions: any UV set, tangent or colour takes the general path.
TEST(Facet, BareOnlyWhereTheMeshHasNoUvsTangentsOrColours) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.indices = {0, 1, 2};
    const Transform xf = Transform::translate({1, 2, 3});
    EXPECT_EQ(make_facet(mesh, xf, 0).flags, Facet::kNormal | Facet::kFlat | Facet::kBare);
    TriangleMesh uv1 = mesh;
    uv1.uv1 = {{0, 0}, {1, 0}, {0, 1}};
    TriangleMesh tangents = mesh;
    tangents.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
    TriangleMesh colours = mesh;
    colours.colors = {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}};
    for (const TriangleMesh* m : {&uv1, &tangents, &colours})
        EXPECT_EQ(make_facet(*m, xf, 0).flags, Facet::kNormal | Facet::kFlat);
}

TEST(Facet, OneForEachTriangleAndNoneForDeformingMeshes) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 3, 0, 3, 1};
    const Transform xf = Transform::trs({1, 2, 3}, Quat{0, 0, 0.6f, 0.8f}, {1, 2, 3});
    const std::vector<Facet> facets = make_facets(mesh, xf);
    ASSERT_EQ(facets.size(), 3u);
    for (uint32_t prim = 0; prim < 3; ++prim) {
        const Facet f = make_facet(mesh, xf, prim);
        EXPECT_EQ(facets[prim].flags, f.flags);
        EXPECT_TRUE(test::same_bits(&facets[prim].ng.x, &f.ng.x, 3)) << prim;
    }
    EXPECT_EQ(facets[0].flags, Facet::kNormal | Facet::kFlat | Facet::kBare);
    EXPECT_EQ(facets[1].flags, Facet::kNormal);  // shading normals differ: not bare either

    TriangleMesh moving = mesh;
    moving.motion_positions = {mesh.positions, mesh.positions};
    EXPECT_TRUE(make_facets(moving, xf).empty());
    TriangleMesh bending = mesh;
    bending.motion_normals = {mesh.normals, mesh.normals};
    EXPECT_TRUE(make_facets(bending, xf).empty());
}

}  // namespace
}  // namespace penumbra
