// Single- and double-sided triangle lights: which side emits (glTF's front face, mirrored
// instances included), the power, and that sample_Li, pdf_Li, pdf_at and the emission
// shade() finds at a hit all agree on it.
#include "core/lights/triangle_light.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/lights/light_set.h"
#include "core/scene/motion.h"
#include "core/surface_point.h"
#include "materials/material.h"
#include "support/statistics/chi2.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

const float kLe = 3;

// One emissive quad, object-space front face +Y (counter-clockwise seen from above),
// the unit square [0,1] x [0,1] in x and z, placed by `to_world`.
Scene quad_scene(bool double_sided, const Transform& to_world) {
    Scene scene;
    MaterialDesc m;
    m.base_color = {0, 0, 0, 1};
    m.metallic = 0;
    m.specular = 0;
    m.emissive = Spectrum(kLe);
    m.double_sided = double_sided;
    scene.materials.push_back(m);
    const uint32_t quad =
        test::add_quad_object(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0);
    test::add_instance(scene, quad, to_world);
    return scene;
}

// How many of n light samples from ref come back (all or none for a planar triangle).
int sample_count(const TriangleLight& light, Vec3 ref, float time, int n = 64) {
    int count = 0;
    Rng rng(11);
    for (int i = 0; i < n; ++i)
        if (light.sample_Li({ref, {0, 1, 0}}, {rng.next_float(), rng.next_float()}, time)) ++count;
    return count;
}

TEST(TriangleLight, SingleSidedEmitsFromItsFrontOnlyAndTwoSidedFromBoth) {
    // Triangle 0 of the quad: (0,0,0), (0,0,1), (1,0,1); its centroid is below q.
    const Vec3 c(1.0f / 3, 0, 2.0f / 3);
    const Vec3 above = c + Vec3(0.1f, 0.7f, -0.2f), below = c + Vec3(0.1f, -0.7f, -0.2f);
    for (bool two_sided : {false, true}) {
        const Scene scene = quad_scene(two_sided, Transform());
        const TriangleLight light(scene, 0, 0, 0, Spectrum(kLe));
        EXPECT_EQ(light.two_sided(), two_sided);
        // pi A Le per emitting side (A = 1/2).
        EXPECT_NEAR(light.power(), (two_sided ? 2 : 1) * kPi * 0.5f * kLe, 1e-5f);
        EXPECT_EQ(sample_count(light, above, 0), 64);
        EXPECT_EQ(sample_count(light, below, 0), two_sided ? 64 : 0);
        const float pdf_above = light.pdf_Li({above, {}}, normalize(c - above), 0);
        const float pdf_below = light.pdf_Li({below, {}}, normalize(c - below), 0);
        EXPECT_GT(pdf_above, 0);
        // The two points are mirror images through the plane: equal densities.
        EXPECT_NEAR(pdf_below, two_sided ? pdf_above : 0.0f, 1e-4f * pdf_above);
        EXPECT_NEAR(light.pdf_at({above, {}}, c, 0), pdf_above, 1e-4f * pdf_above);
        EXPECT_NEAR(light.pdf_at({below, {}}, c, 0), pdf_below, 1e-4f * pdf_above);
    }
}

// For refs on both sides and random points of both triangles: sample_Li, pdf_Li and
// pdf_at are nonzero exactly where shade() finds emission towards ref at that point, and
// that is the side `front` (the world direction of the glTF front face) points to.
void expect_sides_agree_for(const Scene& scene, float time, Vec3 front, const char* what,
                            TriangleSampling sampling) {
    const LightSet lights(scene, nullptr, {LightSamplerType::Power, sampling});
    ASSERT_EQ(lights.triangle_light_count(), 2u) << what;
    Rng rng(3);
    int emitting = 0, dark = 0;
    for (uint32_t prim = 0; prim < 2; ++prim) {
        const TriangleLight& light = *lights.triangle_light(0, 0, prim);
        for (int i = 0; i < 200; ++i) {
            Hit hit;
            hit.instance = 0;
            hit.prim = prim;
            hit.b1 = rng.next_float();
            hit.b2 = rng.next_float() * (1 - hit.b1);
            Ray ray;
            ray.time = time;
            ray.d = Vec3(0, -1, 0);
            const SurfacePoint sp = make_surface_point(scene, ray, hit);
            // A ref on either side, 0.2 to 2 away, not too grazing.
            const Vec3 d = normalize(
                Vec3(rng.next_float() - 0.5f, 0.5f + rng.next_float(), rng.next_float() - 0.5f));
            const Transform xf = instance_transform_at(scene.instances[0], time);
            const Vec3 n_world = normalize(xf.normal({0, 1, 0}));
            const Frame frame = Frame::from_normal(n_world);
            Vec3 w = frame.to_world(d);
            if (i % 2) w = -w;  // the other side
            const Vec3 ref = sp.p + w * (0.2f + 1.8f * rng.next_float());
            const Vec3 wo = normalize(ref - sp.p);
            const bool lit = !is_black(shade(scene, sp, wo).emission);
            const bool faces_ref = dot(front, wo) > 0;
            EXPECT_EQ(lit, faces_ref || light.two_sided()) << what << " prim " << prim;
            EXPECT_EQ(light.pdf_at({ref, {}}, sp.p, time) > 0, lit) << what;
            EXPECT_EQ(light.pdf_Li({ref, {}}, -wo, time) > 0, lit) << what;
            EXPECT_EQ(sample_count(light, ref, time, 4) == 4, lit) << what;
            (lit ? emitting : dark)++;
        }
    }
    // Both sides were tried.
    EXPECT_GT(emitting, 100) << what;
    if (!scene.materials[0].double_sided) {
        EXPECT_GT(dark, 100) << what;
    }
}

// Both strategies: area sampling and solid-angle sampling decide the side alike.
void expect_sides_agree(const Scene& scene, float time, Vec3 front, const char* what) {
    expect_sides_agree_for(scene, time, front, what, TriangleSampling::Area);
    expect_sides_agree_for(scene, time, front, what, TriangleSampling::SolidAngle);
}

TEST(TriangleLight, MirroredInstancesKeepTheGltfFrontFace) {
    const float k = 1 / std::sqrt(0.95f);  // a unit quaternion
    const Quat tilt{0.3f * k, 0.1f * k, -0.2f * k, 0.9f * k};
    // Mirrored within the quad's plane: the world winding now faces -Y, but glTF's front
    // face (clockwise under a negative determinant) is still +Y.
    expect_sides_agree(quad_scene(false, Transform::scale({-1, 1, 1})), 0, {0, 1, 0},
                       "mirrored in x");
    // Mirrored through the plane: the winding still faces +Y in world space, the front -Y.
    expect_sides_agree(quad_scene(false, Transform::scale({1, -2, 1})), 0, {0, -1, 0},
                       "mirrored in y");
    const Transform rotated = Transform::rotate(tilt) * Transform::scale({0.5f, 1, -3});
    expect_sides_agree(quad_scene(false, rotated), 0,
                       normalize(Transform::rotate(tilt).vector({0, 1, 0})),
                       "rotated, mirrored in z");
    expect_sides_agree(quad_scene(false, Transform()), 0, {0, 1, 0}, "identity");
    expect_sides_agree(quad_scene(true, Transform::scale({1, -1, 1})), 0, {0, -1, 0},
                       "two-sided, mirrored");
}

TEST(TriangleLight, FrontFaceFollowsTheWindingWhereTheNormalsDisagree) {
    // glTF defines the front face by winding alone; shading normals that point to the
    // back (make_surface_point then turns ng their way) do not move the emitting side.
    for (const Transform& xf : {Transform(), Transform::scale({1, -1, 1})}) {
        Scene scene = quad_scene(false, xf);
        for (Vec3& n : scene.meshes[0].normals) n = -n;
        expect_sides_agree(scene, 0, normalize(xf.normal({0, 1, 0})), "normals reversed");
    }
}

TEST(TriangleLight, MovingMirroredInstanceEmitsWhereItsFrontFaceIsAtTheRaysTime) {
    // A mirrored quad turning half a turn about X over the shutter: its front face (-Y at
    // shutter open, from the mirror through the plane) looks along -Z halfway through and
    // up at shutter close.
    Scene scene = quad_scene(false, Transform::scale({1, -1, 1}));
    std::vector<Transform> steps;
    for (int k = 0; k <= 4; ++k) {
        const float angle = 0.25f * kPi * k;
        const Quat q{std::sin(0.5f * angle), 0, 0, std::cos(0.5f * angle)};
        steps.push_back(Transform::rotate(q) * Transform::scale({1, -1, 1}));
    }
    scene.instances[0].motion = steps;
    for (float time : {0.0f, 0.3f, 0.5f, 1.0f}) {
        const Transform xf = instance_transform_at(scene.instances[0], time);
        ASSERT_TRUE(xf.swaps_handedness());
        const Vec3 front = normalize(xf.normal({0, 1, 0}));
        expect_sides_agree(scene, time, front, "moving mirrored");
    }
    // At time 0.5 the front is a quarter turn of -Y about X.
    const Vec3 half = normalize(instance_transform_at(scene.instances[0], 0.5f).normal({0, 1, 0}));
    EXPECT_NEAR(half.z, -1.0f, 1e-3f);
}

TEST(TriangleLight, DeformingMeshEmitsFromItsWindingAtTheRaysTime) {
    // The quad folds over within the shutter (x -> -x): its winding, and with it the
    // front face, turns from +Y to -Y at time 0.5, while the normals keep saying +Y.
    Scene scene = quad_scene(false, Transform());
    TriangleMesh& mesh = scene.meshes[0];
    std::vector<Vec3> folded = mesh.positions;
    for (Vec3& p : folded) p.x = -p.x;
    mesh.motion_positions = {mesh.positions, folded};
    expect_sides_agree(scene, 0.25f, {0, 1, 0}, "deforming, before the fold");
    expect_sides_agree(scene, 0.75f, {0, -1, 0}, "deforming, after the fold");
}

TEST(TriangleLight, TwoSidedFromBehindAndMirroredFromTheFrontMatchTheirPdf) {
    // The back of a two-sided quad, and the front of a mirrored one whose world winding
    // faces away from the receiver: sample_Li follows pdf_Li there too.
    struct Case {
        bool two_sided;
        Transform xf;
        const char* what;
    };
    const Case cases[] = {
        {true, Transform::translate({-1.2f, 0.4f, -0.3f}) * Transform::scale({2.5f, 1, 2}),
         "two-sided, receiver behind"},
        {false, Transform::translate({-1.2f, 0.4f, -0.3f}) * Transform::scale({2.5f, -1, 2}),
         "mirrored, receiver in front"},
    };
    const ShadingPoint ref{{0, 0, 0}, {0, 1, 0}};
    for (const Case& c : cases) {
        const Scene scene = quad_scene(c.two_sided, c.xf);
        const TriangleLight light(scene, 0, 0, 1, Spectrum(kLe));
        test::SphereChi2Options opt;
        opt.significance = test::sidak_significance(0.01, 2);
        opt.cos_bins = 20;
        opt.phi_bins = 40;
        const auto r = test::chi2_sphere(
            [&](Rng& rng) -> std::optional<Vec3> {
                const auto ls = light.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
                if (!ls) return std::nullopt;
                EXPECT_NEAR(ls->pdf, light.pdf_Li(ref, ls->wi, 0), 1e-3f * ls->pdf);
                return ls->wi;
            },
            [&](Vec3 w) { return light.pdf_Li(ref, w, 0); }, opt);
        EXPECT_TRUE(r.passed) << c.what << "\n" << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 1e-2) << c.what;
    }
}

}  // namespace
}  // namespace penumbra
