// Robust secondary rays (core/surface_point.*) on the hard cases of scenes/hard/: no
// self-shadowing acne on a lit plane at any distance from the origin and any light
// angle, no light leaking between sheets 1e-4 apart, Hanika's lifted origin, and shadow
// rays from a lifted origin that stop short of the point they were aimed at.
#include "core/surface_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/camera/orthographic_camera.h"
#include "core/lights/directional_light.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builder.h"
#include "support/paths.h"
#include "support/render_scene.h"

namespace penumbra {
namespace {

constexpr float kAlbedo = 0.8f;  // scenes/hard/: every material is Lambertian 0.8

TEST(SmoothSurfacePoint, FlatTriangleKeepsThePoint) {
    const Vec3 v[3] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    const Vec3 n[3] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const float b[3] = {0.2f, 0.3f, 0.5f};
    const Vec3 p = v[0] * b[0] + v[1] * b[1] + v[2] * b[2];
    const Vec3 q = smooth_surface_point(p, v, n, b);
    EXPECT_EQ(q.x, p.x);
    EXPECT_EQ(q.y, p.y);
    EXPECT_EQ(q.z, p.z);
}

// One triangle in a tilted plane with the given vertex normal at all three vertices,
// placed by xf; the surface point at barycentrics (0.3, 0.5).
SurfacePoint point_on_triangle(Vec3 normal, const Transform& xf) {
    Scene scene;
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0.3f, 0}, {0.2f, 0.1f, 1}};
    mesh.normals = {normal, normal, normal};
    mesh.indices = {0, 1, 2};
    test::add_instance(scene, test::add_mesh_object(scene, mesh, "triangle"), xf);
    Ray ray;
    ray.d = {0, -1, 0};
    Hit hit;
    hit.t = 1;
    hit.b1 = 0.3f;
    hit.b2 = 0.5f;
    return make_surface_point(scene, ray, hit);
}

TEST(SmoothSurfacePoint, FlatShadedFacetIsNotLiftedAndTiltedNormalsAre) {
    const Vec3 face = normalize(cross(Vec3(1, 0.3f, 0), Vec3(0.2f, 0.1f, 1)));
    const float s = std::sqrt(0.5f);
    for (const Transform& xf : {Transform(), Transform::translate({1, -2, 3}),
                                Transform::trs({0.5f, 0, 0}, Quat{0, s, 0, s}, {2, 1, 0.5f})}) {
        // Flat shading: p exactly, and the normal is the face normal.
        const SurfacePoint flat = point_on_triangle(face, xf);
        EXPECT_EQ(flat.p_smooth.x, flat.p.x);
        EXPECT_EQ(flat.p_smooth.y, flat.p.y);
        EXPECT_EQ(flat.p_smooth.z, flat.p.z);
        EXPECT_GT(dot(flat.ns, flat.ng), 1 - 1e-6f);
        // Equal normals that lean off the face normal put vertex planes through the
        // facet: Hanika's lift still applies.
        const SurfacePoint tilted = point_on_triangle(normalize(face + Vec3(0.3f, 0, 0)), xf);
        EXPECT_GT(length(tilted.p_smooth - tilted.p), 1e-3f);
    }
}

TEST(SmoothSurfacePoint, ConvexFacetIsLiftedTowardsTheSphere) {
    // A facet of the unit sphere with vertex normals = positions: its centre lies inside
    // the sphere; the lifted point must be further out. The tangent planes lie outside
    // the sphere, so it may overshoot, but by less than the facet's own depth.
    const Vec3 v[3] = {normalize(Vec3(1, 0.2f, 0)), normalize(Vec3(0.9f, 0.2f, 0.4f)),
                       normalize(Vec3(0.95f, 0.5f, 0.2f))};
    const float b[3] = {1 / 3.0f, 1 / 3.0f, 1 / 3.0f};
    const Vec3 p = (v[0] + v[1] + v[2]) / 3;
    const Vec3 q = smooth_surface_point(p, v, v, b);
    EXPECT_LT(length(p), 0.99f);
    EXPECT_GT(length(q), length(p) + 0.5f * (1 - length(p)));
    EXPECT_LT(length(q) - 1, 1 - length(p));
    // Zero normals (bad input) leave the point where it is.
    const Vec3 zero[3] = {};
    const Vec3 r = smooth_surface_point(p, v, zero, b);
    EXPECT_EQ(r.x, p.x);
}

TEST(SpawnRay, ShadowRayFromALiftedOriginStopsShortOfItsTarget) {
    // A point on a smooth sphere's facet, lifted 1e-3 along the normal (about what a
    // 48-segment sphere of radius 0.3 gets), aimed at a light point 0.8 away. Kept parallel
    // to w, the segment ended 1e-3 beyond the target, inside the area light sampled
    // there, which then shadowed its own light (efficiency.py's Lambertian Cornell box).
    SurfacePoint sp;
    sp.p = {0.35f, 0.2f, 0.3f};
    sp.ng = sp.ns = normalize(Vec3(0.1f, 1, 0.05f));
    sp.p_smooth = sp.p + sp.ns * 1e-3f;
    sp.p_error = Vec3(1e-7f);
    const Vec3 target = {0.1f, 0.999f, 0.1f};
    const float dist = length(target - sp.p);
    const Vec3 w = (target - sp.p) / dist;
    const Ray r = spawn_ray(sp, w, dist, 0.0f);
    const Vec3 end = r.o + r.d * r.tmax;
    EXPECT_GT(dot(target - end, r.d), 0.0f) << "the segment reaches past its target";
    EXPECT_LT(length(target - end), 1e-3f * dist);
    EXPECT_NEAR(length(r.d), 1.0f, 1e-6f);
    EXPECT_GT(dot(r.o - sp.p, sp.ns), 0.5e-3f);  // still from the lifted origin
    // Rays without an end (BSDF continuations) keep their direction.
    const Ray open = spawn_ray(sp, w, std::numeric_limits<float>::infinity(), 0.0f);
    EXPECT_EQ(open.d.x, w.x);
    EXPECT_EQ(open.tmax, std::numeric_limits<float>::infinity());
}

// A vertex's shared origins (RayOrigins) give every ray the bits spawn_ray gives it
// alone: rays on both sides of a lifted point whose shading normal is tilted from its
// geometric one, so that the two sides' origins differ in base point and direction.
TEST(SpawnRay, AVertexsSharedOriginsGiveEachRayItsOwnBits) {
    SurfacePoint sp;
    sp.p = {12.35f, -0.2f, 3.3f};
    sp.ng = normalize(Vec3(0.1f, 1, 0.05f));
    sp.ns = normalize(Vec3(0.4f, 1, -0.3f));
    sp.p_smooth = sp.p + sp.ns * 1e-3f;
    sp.p_error = Vec3(2e-6f, 1e-7f, 5e-7f);
    const RayOrigins origins(sp);
    int outside = 0, inside = 0;
    for (int i = 0; i < 2000; ++i) {
        // Directions over the whole sphere (a spiral), shadow rays and open ones.
        const float z = 1 - (i + 0.5f) / 1000, phi = 2.39996f * i;
        const float r = std::sqrt(std::max(0.0f, 1 - z * z));
        const Vec3 w(r * std::cos(phi), z, r * std::sin(phi));
        const float dist = i % 2 ? 0.7f : std::numeric_limits<float>::infinity();
        // spawn_ray aims at sp.p + w * dist; spawn_ray_to at the point it is given.
        const Ray a = spawn_ray_to(origins, w, dist, sp.p + w * dist, 0.25f),
                  b = spawn_ray(sp, w, dist, 0.25f);
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(a.o[k], b.o[k]) << i;
            ASSERT_EQ(a.d[k], b.d[k]) << i;
        }
        ASSERT_EQ(a.tmax, b.tmax) << i;
        ASSERT_EQ(a.time, b.time) << i;
        (dot(w, sp.ns) > 0 ? outside : inside) += 1;
    }
    EXPECT_GT(outside, 500);
    EXPECT_GT(inside, 500);
}

// The plane's unit normal in world space and a unit tangent.
void plane_frame(const Scene& scene, Vec3* n, Vec3* t) {
    const Transform& xf = scene.instances[0].to_world;
    *n = normalize(xf.normal({0, 1, 0}));
    *t = normalize(xf.vector({1, 0, 0}));
}

// Falsely shadowed pixels of the acne plane moved `offset` away, lit from elevation
// `deg` above the plane: an unshadowed Lambertian plane has the same value everywhere.
int acne_pixels(Vec3 offset, float deg, float* min_ratio) {
    Scene scene = load_gltf(test::source_path("scenes/hard/acne-plane.gltf"));
    test::transform_scene(scene, Transform::translate(offset));
    Vec3 n, t;
    plane_frame(scene, &n, &t);
    const float elev = deg * kPi / 180;
    const Vec3 to_light = n * std::sin(elev) + t * std::cos(elev);
    scene.lights.clear();
    scene.lights.push_back(std::make_unique<DirectionalLight>(-to_light, Spectrum(1), 10.0f));
    const Vec3 centre = scene.instances[0].to_world.point({0, 0, 0});
    // Looking straight at the plane, up along the tangent the light comes from.
    const int res = 40;
    const OrthographicCamera camera(Transform::look_at(centre + n, centre, t), 0.9f, 0.9f, res,
                                    res);
    const test::SceneRender r = test::render_scene(scene, camera, "basic", 1);
    const float expected = kAlbedo / kPi * std::sin(elev);
    int bad = 0;
    *min_ratio = 1e30f;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const float v = test::pixel_mean(r.image, x, y);
            *min_ratio = std::min(*min_ratio, v / expected);
            // The only light-dependent error is float rounding (well below 1e-3).
            if (!(v > expected * (1 - 1e-3f))) ++bad;
        }
    return bad;
}

TEST(SelfIntersection, LitPlaneHasNoAcneAtAnyDistanceOrLightAngle) {
    const Vec3 dir = normalize(Vec3(1, 0.6f, -0.8f));
    for (const float d : {1e-3f, 1.0f, 1e3f, 1e5f})
        for (const float deg : {0.5f, 2.0f, 10.0f, 45.0f, 90.0f}) {
            float min_ratio = 0;
            EXPECT_EQ(acne_pixels(dir * d, deg, &min_ratio), 0)
                << "plane at distance " << d << ", light " << deg
                << " degrees above it: darkest pixel at " << min_ratio << " of the lit value";
        }
}

// The camera sits between two sheets 1e-4 apart and looks down at the lower one, which
// the upper one shades from the sun above: any light is a leak through the upper sheet.
float leaked_light(Vec3 offset, float deg) {
    Scene scene = load_gltf(test::source_path("scenes/hard/thin-sheets.gltf"));
    test::transform_scene(scene, Transform::translate(offset));
    const float elev = deg * kPi / 180;
    scene.lights.clear();
    scene.lights.push_back(std::make_unique<DirectionalLight>(
        -Vec3(std::cos(elev), std::sin(elev), 0), Spectrum(1), 10.0f));
    const Vec3 eye = offset + Vec3(0, 0.5e-4f, 0);
    const int res = 32;
    const OrthographicCamera camera(Transform::look_at(eye, eye - Vec3(0, 1, 0), {0, 0, 1}), 1,
                                    1, res, res);
    const test::SceneRender r = test::render_scene(scene, camera, "basic", 1);
    float worst = 0;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const float v = test::pixel_mean(r.image, x, y);
            worst = std::isfinite(v) ? std::max(worst, v) : 1e30f;
        }
    return worst;
}

TEST(SelfIntersection, SheetsATenThousandthApartDoNotLeak) {
    // Offsets are a few ULPs of the coordinates along the normal (surface_point.cpp):
    // 1e-4 stays resolved up to coordinates of about 100.
    for (const Vec3 offset : {Vec3(0), Vec3(1, 0, -1), Vec3(-7, 3, 9), Vec3(60, -40, 90)})
        for (const float deg : {90.0f, 30.0f, 5.0f})
            EXPECT_EQ(leaked_light(offset, deg), 0.0f)
                << "sheets at " << offset.x << "," << offset.y << "," << offset.z << ", sun at "
                << deg << " degrees";
    // The same camera above both sheets sees the lit upper one: the setup can fail.
    Scene scene = load_gltf(test::source_path("scenes/hard/thin-sheets.gltf"));
    const OrthographicCamera above(Transform::look_at({0, 1, 0}, {0, 0, 0}, {0, 0, 1}), 1, 1, 8,
                                   8);
    const test::SceneRender r = test::render_scene(scene, above, "basic", 1);
    EXPECT_NEAR(test::pixel_mean(r.image, 4, 4), kAlbedo / kPi, 1e-4f);
}

}  // namespace
}  // namespace penumbra
