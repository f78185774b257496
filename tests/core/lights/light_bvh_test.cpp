// Light selection for a receiver (uniform, power, light BVH): the pmf sums to 1 over the
// lights and agrees with what sample() returns and how often, the BVH gives zero only to
// lights that cannot reach the receiver, and irradiance from many emitters is unbiased.
#include "core/lights/light_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/lights/light_set.h"
#include "core/lights/point_light.h"
#include "core/lights/spot_light.h"
#include "core/scene/emission.h"
#include "support/statistics/chi2.h"
#include "support/statistics/estimate.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

constexpr LightSamplerType kTypes[] = {LightSamplerType::Uniform, LightSamplerType::Power,
                                       LightSamplerType::Bvh};
const char* name(LightSamplerType t) {
    return t == LightSamplerType::Uniform ? "uniform"
           : t == LightSamplerType::Power ? "power"
                                          : "bvh";
}

Vec3 random_unit(Rng& rng) {
    const float z = 1 - 2 * rng.next_float(), phi = 2 * kPi * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// n emissive triangles of varied size, orientation and emission (materials 0-3: one- and
// two-sided, dim and bright) in the box [lo, hi]. With `facing` (unit), they are flat in
// planes normal to it, fronts alternately along +facing (even) and -facing (odd).
Scene many_triangles(int n, Vec3 lo, Vec3 hi, uint64_t seed, Vec3 facing = Vec3(0)) {
    Scene scene;
    for (int k = 0; k < 4; ++k) {
        MaterialDesc m;
        m.emissive = Spectrum(k % 2 ? 8.0f : 0.3f, 1.0f, 0.5f);
        m.double_sided = k >= 2;
        scene.materials.push_back(m);
    }
    Rng rng(seed);
    for (int i = 0; i < n; ++i) {
        const Vec3 c = lo + (hi - lo) * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
        const float size = 0.05f + 0.35f * rng.next_float();
        TriangleMesh mesh;
        Vec3 a = c + random_unit(rng) * size, b = c + random_unit(rng) * size,
             d = c + random_unit(rng) * size;
        if (facing != Vec3(0)) {
            a = a - facing * dot(a - c, facing);
            b = b - facing * dot(b - c, facing);
            d = d - facing * dot(d - c, facing);
            if ((dot(cross(b - a, d - a), facing) > 0) != (i % 2 == 0)) std::swap(b, d);
        }
        mesh.positions = {a, b, d};
        const Vec3 nrm = normalize(cross(b - a, d - a));
        mesh.normals = {nrm, nrm, nrm};
        mesh.indices = {0, 1, 2};
        mesh.material = int(rng.next_below(4));
        test::add_instance(scene, test::add_mesh_object(scene, std::move(mesh), "tri"),
                           Transform());
    }
    return scene;
}

void add_punctual(Scene& scene) {
    scene.lights.push_back(std::make_unique<PointLight>(Vec3(0.5f, 0.2f, -0.3f), Spectrum(2)));
    scene.lights.push_back(std::make_unique<SpotLight>(Vec3(-1, 1, 0.5f), normalize(Vec3(1, -1, 0)),
                                                       Spectrum(20), 0.2f, 0.4f));
}

std::vector<ShadingPoint> receivers(int n, uint64_t seed) {
    Rng rng(seed);
    std::vector<ShadingPoint> r;
    for (int i = 0; i < n; ++i) {
        const Vec3 p(6 * rng.next_float() - 3, 6 * rng.next_float() - 3, 6 * rng.next_float() - 3);
        r.push_back({p, i % 4 == 3 ? Vec3(0) : random_unit(rng)});  // some in a medium
    }
    return r;
}

// With two-sided emitters only, some light reaches every receiver below every node, so
// the pmf sums to 1. (Single-sided ones can leave the BVH a node whose children both
// face away: then sample() returns nothing, with the missing probability; see below.)
TEST(LightSet, PmfSumsToOneAndMatchesSample) {
    Scene scene = many_triangles(300, Vec3(-2), Vec3(2), 1);
    for (MaterialDesc& m : scene.materials) m.double_sided = true;
    add_punctual(scene);
    for (LightSamplerType type : kTypes) {
        const LightSet lights(scene, std::make_unique<EnvironmentLight>(Spectrum(0.5f), 10.0f),
                              {type, TriangleSampling::SolidAngle});
        ASSERT_EQ(lights.lights().size(), 303u);
        Rng rng(9);
        for (const ShadingPoint& ref : receivers(40, 2)) {
            double sum = 0;
            for (const Light* l : lights.lights()) sum += lights.pmf(ref, l);
            EXPECT_NEAR(sum, 1.0, 1e-4) << name(type);
            for (int i = 0; i < 20; ++i) {
                const auto s = lights.sample(ref, rng.next_float());
                ASSERT_TRUE(s) << name(type);
                EXPECT_NEAR(s->pmf, lights.pmf(ref, s->light), 1e-5f * s->pmf) << name(type);
            }
        }
    }
}

// auto: the BVH from kAutoBvhLights bounded lights on (the environment does not count).
TEST(LightSet, AutoChoosesTheBvhForManyLights) {
    Scene few = many_triangles(int(kAutoBvhLights) - 1, Vec3(-2), Vec3(2), 1);
    const LightSet a(few, std::make_unique<EnvironmentLight>(Spectrum(0.5f), 10.0f));
    EXPECT_EQ(a.sampler_type(), LightSamplerType::Power);
    Scene many = many_triangles(int(kAutoBvhLights), Vec3(-2), Vec3(2), 1);
    const LightSet b(many, nullptr);
    EXPECT_EQ(b.sampler_type(), LightSamplerType::Bvh);
    EXPECT_EQ(
        LightSet(many, nullptr, {LightSamplerType::Power, TriangleSampling::Area}).sampler_type(),
        LightSamplerType::Power);
}

// Frequencies of every light and of "no light" (single-sided emitters facing away) against
// the pmf and 1 - its sum.
TEST(LightSet, BvhChoosesLightsAsOftenAsItsPmfSays) {
    Scene scene = many_triangles(200, Vec3(-2), Vec3(2), 4);
    add_punctual(scene);
    const LightSet lights(scene, std::make_unique<EnvironmentLight>(Spectrum(0.5f), 10.0f),
                          {LightSamplerType::Bvh, TriangleSampling::SolidAngle});
    const std::vector<ShadingPoint> refs = receivers(4, 5);
    const double level = test::sidak_significance(0.01, int(refs.size()));
    for (const ShadingPoint& ref : refs) {
        const auto& all = lights.lights();
        std::vector<double> observed(all.size() + 1), expected(all.size() + 1);
        const int n = 400000;
        Rng rng(6);
        for (int i = 0; i < n; ++i) {
            const auto s = lights.sample(ref, rng.next_float());
            observed[s ? std::find(all.begin(), all.end(), s->light) - all.begin() : all.size()] +=
                1;
        }
        double sum = 0;
        for (size_t k = 0; k < all.size(); ++k) {
            expected[k] = n * double(lights.pmf(ref, all[k]));
            sum += lights.pmf(ref, all[k]);
        }
        EXPECT_LE(sum, 1 + 1e-5);
        expected[all.size()] = n * std::max(0.0, 1 - sum);
        const auto r = test::chi2_compare(observed, expected, n, level,
                                          [](size_t k) { return std::to_string(k); });
        EXPECT_TRUE(r.passed) << r.report;
    }
}

// Single-sided sheets facing one way: the tree must give zero only to lights that send
// nothing to the receiver, and nothing at all behind every one of them.
TEST(LightSet, BvhIgnoresOnlyLightsThatCannotReach) {
    Scene scene = many_triangles(200, Vec3(-2, -2, -0.5f), Vec3(2, 2, 0.5f), 8, Vec3(0, 0, 1));
    // Only the single-sided materials.
    for (TriangleMesh& m : scene.meshes) m.material %= 2;
    const LightSet lights(scene, nullptr, {LightSamplerType::Bvh, TriangleSampling::SolidAngle});
    Rng rng(10);
    int zero = 0, nonzero = 0;
    for (const ShadingPoint& ref : receivers(60, 11)) {
        for (const Light* l : lights.lights()) {
            if (lights.pmf(ref, l) > 0) {
                ++nonzero;
                continue;
            }
            ++zero;
            for (int i = 0; i < 8; ++i) {
                const auto ls = l->sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
                const bool n_zero = ref.n == Vec3(0);
                EXPECT_TRUE(!ls || (!n_zero && dot(ls->wi, ref.n) == 0))
                    << "a light with pmf 0 reaches " << ref.p.x << " " << ref.p.y << " " << ref.p.z;
            }
        }
    }
    // The test has power only if the tree does prune.
    EXPECT_GT(zero, nonzero / 10);
    EXPECT_GT(nonzero, 0);
    // Far above the sheets only the fronts facing up reach; far below, only the others.
    // A sheet whose every front faces up leaves a point below it with nothing to choose.
    Scene up = many_triangles(50, Vec3(-1, -1, 0), Vec3(1, 1, 0), 12, Vec3(0, 0, 1));
    for (size_t i = 0; i < up.meshes.size(); ++i) {
        TriangleMesh& m = up.meshes[i];
        m.material = 1;
        if (dot(cross(m.positions[1] - m.positions[0], m.positions[2] - m.positions[0]),
                Vec3(0, 0, 1)) < 0)
            std::swap(m.positions[1], m.positions[2]);
    }
    const LightSet up_lights(up, nullptr, {LightSamplerType::Bvh, TriangleSampling::SolidAngle});
    EXPECT_FALSE(up_lights.sample({{0.1f, 0.2f, -1}, {0, 0, 1}}, 0.5f));
    EXPECT_TRUE(up_lights.sample({{0.1f, 0.2f, 1}, {0, 0, 1}}, 0.5f));
}

// Lambert's formula for a triangle of unit radiance above the receiver's horizon.
double lambert_irradiance(const Vec3 v[3], Vec3 p, Vec3 n) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const Vec3 a = normalize(v[k] - p), b = normalize(v[(k + 1) % 3] - p);
        const Vec3 c = cross(a, b);
        sum += std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0)) * dot(n, c) / length(c);
    }
    return 0.5 * std::abs(sum);
}

// Irradiance (red channel) at a receiver below 300 emitters (single-sided ones facing
// up send nothing) and a
// point light, against the sum of Lambert's formula over those that face it: unbiased
// for every selection and both triangle strategies.
TEST(LightSet, ManyEmitterIrradianceIsUnbiasedForEverySampler) {
    Scene scene = many_triangles(300, Vec3(-2, -2, 1), Vec3(2, 2, 3), 13, Vec3(0, 0, 1));
    scene.lights.push_back(std::make_unique<PointLight>(Vec3(0.5f, 0.2f, 2), Spectrum(2)));
    const ShadingPoint ref{{0.3f, -0.2f, 0}, {0, 0, 1}};
    const Vec3 to_point(0.2f, 0.4f, 2);  // I cos / d^2 from the point light
    double E = 2.0 / length_squared(to_point) * (to_point.z / length(to_point));
    for (const TriangleMesh& m : scene.meshes) {
        const MaterialDesc& mat = scene.materials[m.material];
        const Vec3 v[3] = {m.positions[0], m.positions[1], m.positions[2]};
        if (!emits_towards(mat, cross(v[1] - v[0], v[2] - v[0]), ref.p - v[0])) continue;
        ASSERT_GT(min_component(Vec3(v[0].z, v[1].z, v[2].z)), 0);
        E += mat.emissive.x * lambert_irradiance(v, ref.p, ref.n);
    }
    for (TriangleSampling ts : {TriangleSampling::Area, TriangleSampling::SolidAngle})
        for (LightSamplerType type : kTypes) {
            const LightSet lights(scene, nullptr, {type, ts});
            Rng rng(14);
            const test::Estimate e = test::estimate(400000, [&](uint64_t) {
                const auto s = lights.sample(ref, rng.next_float());
                const Vec2 u(rng.next_float(), rng.next_float());
                if (!s) return 0.0;
                const auto ls = s->light->sample_Li(ref, u, 0);
                if (!ls) return 0.0;
                return double(ls->Li.x) * std::max(0.0f, dot(ls->wi, ref.n)) / (s->pmf * ls->pdf);
            });
            EXPECT_TRUE(test::within(e, E)) << name(type) << " " << int(ts) << ": " << e.mean
                                            << " +- " << e.std_error << " vs " << E;
            EXPECT_LT(e.std_error, 0.01 * E) << name(type);
        }
}

// The tree weighs a node's children in SIMD passes over precomputed bounds: every
// light's lane must give what LightBounds::importance gives for its bounds, for one- and
// two-sided emitters, Lambertian and spot-like spreads, receivers with and without a
// normal, near and far (inside some boxes, too).
TEST(LightBvh, SimdImportanceMatchesLightBounds) {
    Rng rng(21);
    std::vector<std::pair<uint32_t, LightBounds>> lights;
    for (uint32_t i = 0; i < 40; ++i) {
        LightBounds b;
        const Vec3 c(4 * rng.next_float() - 2, 4 * rng.next_float() - 2, 4 * rng.next_float() - 2);
        const Vec3 h(0.5f * rng.next_float(), 0.5f * rng.next_float(),
                     i % 5 == 0 ? 0.0f : 0.5f * rng.next_float());
        b.lo = c - h, b.hi = c + h;
        b.phi = 0.1f + 10 * rng.next_float();
        b.w = random_unit(rng);
        b.cos_theta_o = i % 3 == 0 ? 1.0f : 1 - 2 * rng.next_float();
        b.cos_theta_e = i % 4 == 0 ? std::cos(0.3f * rng.next_float()) : 0.0f;
        b.two_sided = i % 2 == 1;
        lights.emplace_back(i + 7, b);
    }
    const LightBvh bvh(lights);
    int checked = 0, positive = 0;
    for (const ShadingPoint& ref : receivers(200, 22)) {
        for (uint32_t i = 0; i < bvh.node_count(); ++i) {
            float imp[LightBvh::kWidth];
            bvh.child_importance(i, ref.p, ref.n, imp);
            const LightBvh::Node& node = bvh.node(i);
            for (int k = 0; k < LightBvh::kWidth; ++k) {
                if (!(node.leaf_mask >> k & 1)) continue;
                const float want = lights[node.child[k] - 7].second.importance(ref.p, ref.n);
                EXPECT_NEAR(imp[k], want, 2e-4f * want + 1e-7f)
                    << "light " << node.child[k] << " at " << ref.p.x << " " << ref.p.y << " "
                    << ref.p.z;
                ++checked;
                positive += want > 0;
            }
        }
    }
    EXPECT_EQ(checked, 200 * 40);
    EXPECT_GT(positive, checked / 4);
    EXPECT_LT(positive, checked);  // some are cut off: the zero test is exercised
}

// A lone light is the root's only child: chosen with probability 1 where it can reach the
// receiver, never behind it.
TEST(LightBvh, LoneLight) {
    LightBounds b;
    b.lo = Vec3(-0.5f, -0.5f, 0), b.hi = Vec3(0.5f, 0.5f, 0);
    b.phi = 2;
    b.w = Vec3(0, 0, 1);
    b.cos_theta_o = 1, b.cos_theta_e = 0;
    const LightBvh bvh({{3, b}});
    const auto s = bvh.sample(Vec3(0.1f, 0, 1), Vec3(0, 0, -1), 0.7f);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->first, 3u);
    EXPECT_EQ(s->second, 1.0f);
    EXPECT_EQ(bvh.pmf(Vec3(0.1f, 0, 1), Vec3(0, 0, -1), 3), 1.0f);
    EXPECT_FALSE(bvh.sample(Vec3(0.1f, 0, -1), Vec3(0, 0, 1), 0.7f));
    EXPECT_EQ(bvh.pmf(Vec3(0.1f, 0, -1), Vec3(0, 0, 1), 3), 0.0f);
    EXPECT_EQ(bvh.pmf(Vec3(0.1f, 0, 1), Vec3(0, 0, -1), 2), 0.0f);
}

}  // namespace
}  // namespace penumbra
