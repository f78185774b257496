// Solid-angle sampling of triangle lights: Arvo's map is uniform in the subtended solid
// angle, the cosine-warped sampler matches pdf_Li, the inverse recovers the square, and
// irradiance estimates agree with Lambert's formula for both strategies.
#include "core/lights/spherical_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/lights/triangle_light.h"
#include "support/statistics/chi2.h"
#include "support/statistics/estimate.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// The chi-square tests of this file share the overall level.
const double kLevel = test::sidak_significance(0.01, 15);

struct Case {
    const char* name;
    Vec3 v[3];
    Vec3 p, n;
};

// Seen from p, all above its tangent plane (Lambert's formula needs no clipping).
const Case kCases[] = {
    {"regular", {{-0.5f, -0.5f, 2}, {0.7f, -0.3f, 2.2f}, {0, 0.6f, 1.9f}}, {0, 0, 0}, {0, 0, 1}},
    // Large and close: about 2.3 sr, very non-uniform by area.
    {"large close", {{-3, -3, 0.6f}, {4, -2, 0.9f}, {0, 5, 0.5f}}, {0, 0, 0}, {0, 0, 1}},
    // A long sliver, 200:1, at a slant to the receiver.
    // (Off the phi = pi seam of the chi-square cells, where quadrature would miss it.)
    {"sliver",
     {{-2, 0.7f, 1}, {2, 0.71f, 1.2f}, {2, 0.73f, 1.25f}},
     {0.1f, 0, 0},
     {0.3f, 0, 0.954f}},
    // Near the horizon of a tilted receiver.
    {"grazing", {{-1, 2, 0.3f}, {1, 2, 0.3f}, {0, 2.5f, 1.2f}}, {0, 0, 0}, {0, 0.2f, 0.98f}},
};

Scene triangle_scene(const Vec3 v[3]) {
    Scene scene;
    MaterialDesc m;
    m.emissive = Spectrum(1);
    m.double_sided = true;
    scene.materials.push_back(m);
    TriangleMesh mesh;
    mesh.positions = {v[0], v[1], v[2]};
    const Vec3 n = normalize(cross(v[1] - v[0], v[2] - v[0]));
    mesh.normals = {n, n, n};
    mesh.indices = {0, 1, 2};
    mesh.material = 0;
    test::add_instance(scene, test::add_mesh_object(scene, std::move(mesh), "tri"), Transform());
    return scene;
}

// Girard's theorem in double: the spherical excess of the angles between edge planes,
// independent of the Van Oosterom-Strackee formula the code uses.
double girard_solid_angle(const Vec3 v[3], Vec3 p) {
    double d[3][3];
    for (int k = 0; k < 3; ++k) {
        const double x = v[k].x - p.x, y = v[k].y - p.y, z = v[k].z - p.z;
        const double l = std::sqrt(x * x + y * y + z * z);
        d[k][0] = x / l, d[k][1] = y / l, d[k][2] = z / l;
    }
    auto cross3 = [](const double* a, const double* b, double* c) {
        c[0] = a[1] * b[2] - a[2] * b[1];
        c[1] = a[2] * b[0] - a[0] * b[2];
        c[2] = a[0] * b[1] - a[1] * b[0];
        const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        for (int i = 0; i < 3; ++i) c[i] /= l;
    };
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        double n1[3], n2[3];
        cross3(d[k], d[(k + 1) % 3], n1);
        cross3(d[k], d[(k + 2) % 3], n2);
        sum += std::acos(std::clamp(n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2], -1.0, 1.0));
    }
    return sum - M_PI;
}

// Lambert's formula for the irradiance from a polygon of unit radiance above the horizon:
// E = 1/2 sum_i theta_i n . (v_i x v_i+1) / |v_i x v_i+1| (Arvo 1995, "Applications of
// irradiance tensors", eq. 10), in double.
double lambert_irradiance(const Vec3 v[3], Vec3 p, Vec3 n) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const Vec3 a = normalize(v[k] - p), b = normalize(v[(k + 1) % 3] - p);
        const Vec3 c = cross(a, b);
        const double theta = std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0));
        sum += theta * dot(normalize(n), c) / length(c);
    }
    return 0.5 * std::abs(sum);
}

bool hits(const Vec3 v[3], Vec3 p, Vec3 w) {
    const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], pv = cross(w, e2);
    const float det = dot(e1, pv);
    const Vec3 tv = p - v[0];
    const float b1 = dot(tv, pv) / det, b2 = dot(w, cross(tv, e1)) / det;
    return b1 >= 0 && b2 >= 0 && b1 + b2 <= 1 && dot(e2, cross(tv, e1)) / det > 0;
}

TEST(SphericalTriangle, SolidAngleAgreesWithGirard) {
    for (const Case& c : kCases)
        EXPECT_NEAR(triangle_solid_angle(c.v, c.p), girard_solid_angle(c.v, c.p),
                    2e-5 * girard_solid_angle(c.v, c.p))
            << c.name;
}

// Over directions (the sliver is too thin at its tip for the cells' quadrature: it is
// tested over barycentrics below).
TEST(SphericalTriangle, ArvoMapIsUniformInSolidAngle) {
    for (const Case& c : kCases) {
        if (c.name == std::string("sliver")) continue;
        const double omega = girard_solid_angle(c.v, c.p);
        test::SphereChi2Options opt;
        opt.significance = kLevel;
        opt.cos_bins = 30;
        opt.phi_bins = 60;
        const auto r = test::chi2_sphere(
            [&](Rng& rng) -> std::optional<Vec3> {
                const auto b =
                    sample_spherical_triangle(c.v, c.p, {rng.next_float(), rng.next_float()});
                if (!b) return std::nullopt;
                return normalize(c.v[0] * b->x + c.v[1] * b->y + c.v[2] * b->z - c.p);
            },
            [&](Vec3 w) { return hits(c.v, c.p, w) ? 1 / omega : 0.0; }, opt);
        EXPECT_TRUE(r.passed) << c.name << "\n" << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 1e-2) << c.name;
    }
}

// Barycentrics (b1, b2) of point q in the plane of v.
Vec2 barycentrics(const Vec3 v[3], Vec3 q) {
    const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], d = q - v[0];
    const float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    const float d1 = dot(d, e1), d2 = dot(d, e2), det = d11 * d22 - d12 * d12;
    return {(d22 * d1 - d12 * d2) / det, (d11 * d2 - d12 * d1) / det};
}

// A solid-angle density seen as a density over barycentrics (b1, b2) in the unit square:
// times the Jacobian 2 A |cos_light| / d^2 of the map from barycentrics to directions.
double barycentric_density(const Vec3 v[3], Vec3 p, Vec2 b,
                           const std::function<double(Vec3)>& pdf_w) {
    if (b.x < 0 || b.y < 0 || b.x + b.y > 1) return 0;
    const Vec3 q = v[0] * (1 - b.x - b.y) + v[1] * b.x + v[2] * b.y;
    const Vec3 c = cross(v[1] - v[0], v[2] - v[0]);
    const Vec3 d = q - p;
    const double dist2 = length_squared(d);
    const double cos_l = std::abs(dot(c, d)) / (length(c) * std::sqrt(dist2));
    return pdf_w(d / float(std::sqrt(dist2))) * length(c) * cos_l / dist2;
}

// Over the triangle's barycentrics, where a sliver is as wide as any triangle: both the
// plain map (density 1 / solid angle) and the light's warped sampler (its pdf_Li).
TEST(SphericalTriangle, SamplingMatchesItsDensityOverBarycentrics) {
    for (const Case& c : kCases) {
        const double omega = girard_solid_angle(c.v, c.p);
        test::PlanarChi2Options opt;
        opt.significance = kLevel;
        const auto plain = test::chi2_planar(
            [&](Rng& rng) -> std::optional<Vec2> {
                const auto b =
                    sample_spherical_triangle(c.v, c.p, {rng.next_float(), rng.next_float()});
                if (!b) return std::nullopt;
                return Vec2(b->y, b->z);
            },
            [&](Vec2 b) {
                return barycentric_density(c.v, c.p, b, [&](Vec3) { return 1 / omega; });
            },
            opt);
        EXPECT_TRUE(plain.passed) << c.name << "\n" << plain.report;
        EXPECT_NEAR(plain.pdf_integral, 1.0, 2e-3) << c.name;

        const Scene scene = triangle_scene(c.v);
        const TriangleLight light(scene, 0, 0, 0, Spectrum(1), TriangleSampling::SolidAngle);
        const ShadingPoint ref{c.p, normalize(c.n)};
        int edge_misses = 0;
        const auto warped = test::chi2_planar(
            [&](Rng& rng) -> std::optional<Vec2> {
                const auto ls = light.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
                if (!ls) return std::nullopt;
                const Vec2 b = barycentrics(c.v, ref.p + ls->wi * ls->dist);
                const float pdf = light.pdf_Li(ref, ls->wi, 0);
                // pdf_Li's float ray-triangle test can miss a point on the sliver's edge
                // (a region of misses would put samples in cells of zero density).
                if (pdf == 0)
                    ++edge_misses;
                else
                    EXPECT_NEAR(ls->pdf, pdf, 2e-3f * ls->pdf) << c.name;
                return b;
            },
            [&](Vec2 b) {
                return barycentric_density(c.v, c.p, b,
                                           [&](Vec3 w) { return light.pdf_Li(ref, w, 0); });
            },
            opt);
        EXPECT_TRUE(warped.passed) << c.name << "\n" << warped.report;
        EXPECT_LT(edge_misses, 20) << c.name;  // of 200000
        EXPECT_NEAR(warped.pdf_integral, 1.0, 2e-3) << c.name;
    }
}

TEST(SphericalTriangle, InverseRecoversTheSquare) {
    for (const Case& c : kCases) {
        Rng rng(7);
        for (int i = 0; i < 1000; ++i) {
            const Vec2 u(rng.next_float(), rng.next_float());
            const auto b = sample_spherical_triangle(c.v, c.p, u);
            ASSERT_TRUE(b) << c.name;
            const Vec3 w = normalize(c.v[0] * b->x + c.v[1] * b->y + c.v[2] * b->z - c.p);
            const Vec2 back = invert_spherical_triangle_sample(c.v, c.p, w);
            // The sliver's width is 1/200 of its length: its u.x resolves more coarsely.
            EXPECT_NEAR(back.x, u.x, 2e-3f) << c.name << " u " << u.x << " " << u.y;
            EXPECT_NEAR(back.y, u.y, 2e-3f) << c.name << " u " << u.x << " " << u.y;
        }
    }
}

TEST(SphericalTriangle, BilinearWarpMatchesItsPdf) {
    const float w[4] = {0.01f, 0.4f, 1.0f, 0.2f};
    test::PlanarChi2Options opt;
    opt.significance = kLevel;
    const auto r = test::chi2_planar(
        [&](Rng& rng) -> std::optional<Vec2> {
            return sample_bilinear({rng.next_float(), rng.next_float()}, w);
        },
        [&](Vec2 p) { return bilinear_pdf(p, w); }, opt);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-4);
}

// The light's sampler with the receiver-cosine warp, against its own pdf_Li.
TEST(SphericalTriangle, WarpedLightSamplingMatchesPdfLi) {
    for (const Case& c : kCases) {
        if (c.name == std::string("sliver")) continue;
        const Scene scene = triangle_scene(c.v);
        const TriangleLight light(scene, 0, 0, 0, Spectrum(1), TriangleSampling::SolidAngle);
        const ShadingPoint ref{c.p, normalize(c.n)};
        test::SphereChi2Options opt;
        opt.significance = kLevel;
        opt.cos_bins = 30;
        opt.phi_bins = 60;
        const auto r = test::chi2_sphere(
            [&](Rng& rng) -> std::optional<Vec3> {
                const auto ls = light.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
                if (!ls) return std::nullopt;
                EXPECT_NEAR(ls->pdf, light.pdf_Li(ref, ls->wi, 0), 2e-3f * ls->pdf) << c.name;
                return ls->wi;
            },
            [&](Vec3 w) { return light.pdf_Li(ref, w, 0); }, opt);
        EXPECT_TRUE(r.passed) << c.name << "\n" << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 1e-2) << c.name;
    }
}

test::Estimate irradiance(const TriangleLight& light, const ShadingPoint& ref, uint64_t n) {
    Rng rng(3);
    return test::estimate(n, [&](uint64_t) {
        const auto ls = light.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
        if (!ls) return 0.0;
        return double(ls->Li.x) * std::max(0.0f, dot(ls->wi, ref.n)) / ls->pdf;
    });
}

// Unbiased for both strategies, and the warp product pays where the triangle is large
// and close (the case it exists for).
TEST(SphericalTriangle, IrradianceMatchesLambertForBothStrategies) {
    for (const Case& c : kCases) {
        const Scene scene = triangle_scene(c.v);
        const ShadingPoint ref{c.p, normalize(c.n)};
        const double E = lambert_irradiance(c.v, c.p, c.n);
        const uint64_t n = 400000;
        const TriangleLight area(scene, 0, 0, 0, Spectrum(1), TriangleSampling::Area);
        const TriangleLight solid(scene, 0, 0, 0, Spectrum(1), TriangleSampling::SolidAngle);
        const test::Estimate ea = irradiance(area, ref, n), es = irradiance(solid, ref, n);
        EXPECT_TRUE(test::within(ea, E))
            << c.name << " area " << ea.mean << " +- " << ea.std_error << " vs " << E;
        EXPECT_TRUE(test::within(es, E))
            << c.name << " solid angle " << es.mean << " +- " << es.std_error << " vs " << E;
        // Tight: 4 standard errors are a small fraction of E.
        EXPECT_LT(es.std_error, 2e-3 * E) << c.name;
        if (std::string(c.name) == "large close") {
            EXPECT_LT(es.std_error, 0.2 * ea.std_error);
        }
    }
}

// A distant, tiny triangle is sampled by area (pbrt-v4's MinSphericalSampleArea), and
// sample_Li and pdf_Li still agree.
TEST(SphericalTriangle, TinyTrianglesFallBackToAreaSampling) {
    const Vec3 v[3] = {{0, 0, 10}, {0.01f, 0, 10}, {0, 0.01f, 10.001f}};
    const Scene scene = triangle_scene(v);
    const TriangleLight solid(scene, 0, 0, 0, Spectrum(1), TriangleSampling::SolidAngle);
    const TriangleLight area(scene, 0, 0, 0, Spectrum(1), TriangleSampling::Area);
    const ShadingPoint ref{{0, 0, 0}, {0, 0, 1}};
    ASSERT_LT(triangle_solid_angle(v, ref.p), 3e-4f);
    Rng rng(5);
    for (int i = 0; i < 100; ++i) {
        const Vec2 u(rng.next_float(), rng.next_float());
        const auto a = area.sample_Li(ref, u, 0), s = solid.sample_Li(ref, u, 0);
        ASSERT_TRUE(a && s);
        EXPECT_EQ(a->wi, s->wi);
        EXPECT_EQ(a->pdf, s->pdf);
        EXPECT_NEAR(s->pdf, solid.pdf_Li(ref, s->wi, 0), 1e-3f * s->pdf);
    }
}

}  // namespace
}  // namespace penumbra
