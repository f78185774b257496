// GltfBsdf, the glTF lobe stack: clearcoat over sheen over the core. Sampling against the
// pdf (hemisphere, or the sphere where the core transmits) for each layer and their
// combinations, sample/eval/pdf agreement, reciprocity, the white furnace (never a
// gain; exactly the layer's albedo over a black core; factor 0 is the core itself), and
// a coat whose normal differs from the base's.
#include "materials/gltf_bsdf.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

#include "materials/albedo/sheen_albedo.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

struct Stack {
    float metallic = 0, roughness = 0.5f;
    Spectrum base{0.8f, 0.6f, 0.3f};
    float transmission = 0;
    float coat = 0, coat_roughness = 0.2f;
    Vec3 coat_normal{0, 0, 1};
    Spectrum sheen{0, 0, 0};
    float sheen_roughness = 0.5f;
};

std::string describe(const Stack& s, Vec3 wo) {
    std::ostringstream o;
    o << "metallic " << s.metallic << ", roughness " << s.roughness << ", transmission "
      << s.transmission << ", coat " << s.coat << " (roughness " << s.coat_roughness << ", normal "
      << s.coat_normal.x << " " << s.coat_normal.y << " " << s.coat_normal.z << "), sheen "
      << s.sheen.x << " " << s.sheen.y << " " << s.sheen.z << " (roughness " << s.sheen_roughness
      << "), wo.z " << wo.z;
    return o.str();
}

GltfBsdf::Core core_of(const Stack& s) {
    MetalRoughParams p;
    p.base_color = s.base;
    p.metallic = s.metallic;
    p.alpha = s.roughness * s.roughness;
    if (s.transmission == 0) return MetalRoughBsdf(p);
    DielectricParams d;
    d.alpha = p.alpha;
    d.transmittance = s.base;
    return GltfTransmissionBsdf(p, s.transmission, d);
}

GltfBsdf make(const Stack& s) {
    std::optional<SheenLobe> sheen;
    if (max_component(s.sheen) > 0) sheen = SheenLobe(s.sheen, s.sheen_roughness);
    std::optional<ClearcoatLobe> coat;
    if (s.coat > 0)
        coat = ClearcoatLobe(s.coat, s.coat_roughness * s.coat_roughness, normalize(s.coat_normal),
                             MicrofacetType::Ggx);
    return GltfBsdf(core_of(s), sheen, coat);
}

const Vec3 kTilted = normalize(Vec3(0.5f, -0.3f, 1));

// The combinations the brief names, each at a moderate and a grazing view.
std::vector<Stack> combinations() {
    std::vector<Stack> v;
    Stack s;
    s.metallic = 1, s.coat = 1;  // coat over metal
    v.push_back(s);
    s.coat_roughness = 0;  // a mirror coat over rough metal
    v.push_back(s);
    s = Stack{};
    s.metallic = 1, s.roughness = 0.3f, s.coat = 0.7f, s.coat_roughness = 0.6f;
    s.coat_normal = kTilted;  // a coat normal that is not the base's
    v.push_back(s);
    s = Stack{};
    s.sheen = {1, 0.5f, 0.2f}, s.sheen_roughness = 0.3f;  // sheen over dielectric
    v.push_back(s);
    s.sheen_roughness = 1;
    s.roughness = 1;
    v.push_back(s);
    s = Stack{};
    s.sheen = {0.6f, 0.6f, 0.9f}, s.coat = 0.5f, s.coat_roughness = 0.1f;  // all three
    v.push_back(s);
    return v;
}

TEST(GltfBsdf, SamplesFollowThePdf) {
    const std::vector<Stack> stacks = combinations();
    const float cos_os[] = {0.7f, 0.05f};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, stacks.size() * std::size(cos_os));
    int seed = 900;
    for (const Stack& s : stacks)
        for (float cos_o : cos_os) {
            const GltfBsdf bsdf = make(s);
            const Vec3 wo = spherical_direction(cos_o, 0.9f);
            o.seed = ++seed;
            const test::Chi2Result r = test::bsdf_chi2(bsdf, wo, o);
            EXPECT_TRUE(r.passed) << describe(s, wo) << "\n" << r.report;
            // The pdf integrates to the share of non-specular samples.
            const double lost = double(r.lost) / r.samples;
            EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 1e-3)
                << describe(s, wo);
        }
}

TEST(GltfBsdf, HardCasesFollowThePdf) {
    // Grazing views (cos 0.01), roughness 0 and 1 in every layer, narrow coats.
    std::vector<Stack> stacks;
    Stack s;
    s.metallic = 1, s.roughness = 1, s.coat = 1, s.coat_roughness = 1;
    stacks.push_back(s);
    s = Stack{};
    s.roughness = 0, s.sheen = Spectrum(1), s.sheen_roughness = 0;  // over a mirror layer
    stacks.push_back(s);
    s = Stack{};
    s.roughness = 1, s.coat = 1, s.coat_roughness = 0.05f, s.sheen = Spectrum(1);
    s.sheen_roughness = 1;
    stacks.push_back(s);
    s.coat_normal = kTilted;
    stacks.push_back(s);
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, 2 * stacks.size());
    int seed = 930;
    for (const Stack& st : stacks)
        for (float cos_o : {0.01f, 1.0f}) {
            const Vec3 wo = spherical_direction(cos_o, 2.9f);
            o.seed = ++seed;
            const test::Chi2Result r = test::bsdf_chi2(make(st), wo, o);
            EXPECT_TRUE(r.passed) << describe(st, wo) << "\n" << r.report;
        }
}

TEST(GltfBsdf, CoatOverTransmissionSamplesFollowThePdf) {
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, 4);
    int seed = 950;
    for (float roughness : {0.0f, 0.4f})
        for (float cos_o : {0.8f, 0.1f}) {
            Stack s;
            s.roughness = roughness, s.transmission = 1, s.coat = 1, s.coat_roughness = 0.3f;
            s.sheen = {0.5f, 0.5f, 0.5f};
            const Vec3 wo = spherical_direction(cos_o, 2.1f);
            o.seed = ++seed;
            const test::Chi2Result r = test::bsdf_chi2_sphere(make(s), wo, o);
            EXPECT_TRUE(r.passed) << describe(s, wo) << "\n" << r.report;
        }
}

// Stack i of a random set: every layer on and off in turn, mirrors and tilted coats
// among them.
Stack random_stack(Rng& rng, int i) {
    Stack s;
    s.metallic = i % 3 == 0 ? 0.0f : rng.next_float();
    s.roughness = i % 5 == 0 ? 0.0f : rng.next_float();
    s.transmission = i % 4 == 0 ? rng.next_float() : 0.0f;
    s.coat = i % 2 ? rng.next_float() : 0.0f;
    s.coat_roughness = i % 7 == 0 ? 0.0f : rng.next_float();
    s.coat_normal = i % 3 == 1 ? kTilted : Vec3(0, 0, 1);
    if (i % 3 != 2) s.sheen = {rng.next_float(), rng.next_float(), rng.next_float()};
    s.sheen_roughness = rng.next_float();
    return s;
}

TEST(GltfBsdf, SampleAgreesWithEvalAndPdf) {
    Rng rng(31);
    for (int i = 0; i < 300; ++i) {
        const Stack s = random_stack(rng, i);
        const Vec3 wo = test::random_direction(rng, 0.01f);
        EXPECT_EQ(test::check_sample_agreement(make(s), wo, 40, i, Transport::Radiance), "")
            << describe(s, wo);
        // Without transmission and with the coat on the base normal every layer is
        // reciprocal (a tilted coat is a shading normal; see CoatTiltIsAdjoint).
        if (s.transmission == 0 && s.coat_normal.z == 1 && i % 5 == 1) {
            EXPECT_EQ(test::check_reciprocity(make(s), 100, i), "") << describe(s, wo);
        }
    }
}

// eval_pdf is eval and pdf in one pass: the same values bit for bit, for every core
// (metal-rough, transmission, diffuse transmission) under every layer, above and below.
TEST(GltfBsdf, EvalPdfIsEvalAndPdfBitForBit) {
    Rng rng(47);
    int compared = 0;
    for (int i = 0; i < 200; ++i) {
        const Stack s = random_stack(rng, i);
        GltfBsdf::Core core = core_of(s);
        if (i % 6 == 5) {
            MetalRoughParams p;
            p.base_color = s.base;
            p.metallic = 0;
            p.alpha = s.roughness * s.roughness;
            DiffuseTransmissionParams dt;
            dt.factor = rng.next_float();
            dt.color = {0.9f, 0.5f, 0.2f};
            DielectricParams d;
            d.alpha = p.alpha;
            d.transmittance = s.base;
            core = GltfDiffuseTransmissionBsdf(p, dt, s.transmission, d);
        }
        std::optional<SheenLobe> sheen;
        if (max_component(s.sheen) > 0) sheen = SheenLobe(s.sheen, s.sheen_roughness);
        std::optional<ClearcoatLobe> coat;
        if (s.coat > 0)
            coat = ClearcoatLobe(s.coat, s.coat_roughness * s.coat_roughness,
                                 normalize(s.coat_normal), MicrofacetType::Ggx);
        const GltfBsdf bsdf(core, sheen, coat);
        const Vec3 wo = test::random_direction(rng, 0.01f, i % 9 == 0);
        for (int k = 0; k < 30; ++k) {
            const Vec3 wi = test::random_direction(rng, 0.01f, k % 4 == 0);
            const Transport mode = k % 2 ? Transport::Radiance : Transport::Importance;
            float pdf_both;
            const Spectrum f_both = bsdf.eval_pdf(wo, wi, mode, &pdf_both);
            const Spectrum f = bsdf.eval(wo, wi, mode);
            const float pdf = bsdf.pdf(wo, wi, mode);
            ASSERT_EQ(std::memcmp(&f_both, &f, sizeof f), 0) << describe(s, wo);
            ASSERT_EQ(std::memcmp(&pdf_both, &pdf, sizeof pdf), 0) << describe(s, wo);
            compared += pdf > 0;
        }
    }
    EXPECT_GT(compared, 2000);  // most pairs have a density: the values are not all zero
}

// Layers add what they reflect and take it from the layers below: a white material
// reflects at most 1 at every view, grazing ones included.
TEST(GltfBsdf, WhiteFurnaceNeverGains) {
    // The specular albedo table's interpolation error, as in metal_rough_bsdf_test.cpp.
    constexpr float kTableTolerance = 2e-3f;
    int seed = 70;
    for (float roughness : {0.0f, 0.5f, 1.0f})
        for (float metallic : {0.0f, 1.0f})
            for (float coat_roughness : {0.0f, 0.3f, 1.0f})
                for (float cos_o : {1.0f, 0.3f, 0.01f}) {
                    Stack s;
                    s.base = Spectrum(1);
                    s.roughness = roughness, s.metallic = metallic;
                    s.coat = 1, s.coat_roughness = coat_roughness;
                    s.sheen = Spectrum(1), s.sheen_roughness = coat_roughness;
                    s.coat_normal = seed % 2 ? kTilted : Vec3(0, 0, 1);
                    const Vec3 wo = spherical_direction(cos_o, 0.4f);
                    const test::AlbedoEstimate a =
                        test::directional_albedo(make(s), wo, 20000, ++seed);
                    EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + kTableTolerance)
                        << describe(s, wo) << ": albedo " << a.mean.x << " +- " << a.std_error.x;
                }
}

TEST(GltfBsdf, LayerOverBlackCoreReflectsItsAlbedo) {
    // A black non-metal with specular 0 reflects nothing; what remains is the layer
    // alone, whose albedo the tables give: the coat's E_c(wo) at strength 1, the sheen's
    // color E_s(wo). This pins the tables to the lobes they scale by.
    int seed = 80;
    for (float lobe_roughness : {0.05f, 0.3f, 1.0f})
        for (float cos_o : {1.0f, 0.5f, 0.1f}) {
            MetalRoughParams p;
            p.base_color = Spectrum(0);
            p.metallic = 0;
            p.dielectric_f0 = Spectrum(0);
            p.dielectric_f90 = 0;
            const Vec3 wo = spherical_direction(cos_o, 1.1f);
            const ClearcoatLobe coat(1, lobe_roughness * lobe_roughness, Vec3(0, 0, 1),
                                     MicrofacetType::Ggx);
            const test::AlbedoEstimate c =
                test::directional_albedo(GltfBsdf(MetalRoughBsdf(p), {}, coat), wo, 40000, ++seed);
            EXPECT_NEAR(c.mean.x, coat.layer_albedo(wo), 4 * c.std_error.x + 2e-3f)
                << "coat roughness " << lobe_roughness << ", wo.z " << cos_o;
            const SheenLobe sheen(Spectrum(1), lobe_roughness);
            const test::AlbedoEstimate s =
                test::directional_albedo(GltfBsdf(MetalRoughBsdf(p), sheen, {}), wo, 40000, ++seed);
            EXPECT_NEAR(s.mean.x, sheen_albedo(cos_o, lobe_roughness), 4 * s.std_error.x + 2e-3f)
                << "sheen roughness " << lobe_roughness << ", wo.z " << cos_o;
        }
}

TEST(GltfBsdf, FactorZeroIsTheCore) {
    // Strength 0 and black sheen: the stack is exactly its core, value and density.
    Stack s;
    s.metallic = 0.3f;
    const MetalRoughParams p = [&] {
        MetalRoughParams q;
        q.base_color = s.base;
        q.metallic = s.metallic;
        q.alpha = s.roughness * s.roughness;
        return q;
    }();
    const MetalRoughBsdf core(p);
    const GltfBsdf stack(core, SheenLobe(Spectrum(0), 0.5f),
                         ClearcoatLobe(0, 0.1f, kTilted, MicrofacetType::Ggx));
    Rng rng(90);
    for (int i = 0; i < 500; ++i) {
        const Vec3 wo = test::random_direction(rng, 0.01f), wi = test::random_direction(rng, 0.01f);
        EXPECT_EQ(stack.eval(wo, wi, Transport::Radiance), core.eval(wo, wi, Transport::Radiance));
        EXPECT_EQ(stack.pdf(wo, wi, Transport::Radiance), core.pdf(wo, wi, Transport::Radiance));
    }
}

bool finite_nonneg(const Spectrum& f) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(f[c]) || f[c] < 0) return false;
    return true;
}

TEST(GltfBsdf, ExtremesStayFiniteAndConserveEnergy) {
    // Roughness 0 and 1 in every layer, tilted coats, transmission; wo from straight on
    // to exactly grazing and below the surface; eval and pdf against grazing wi.
    const float cosines[] = {1.0f, 1e-2f, 1e-4f, 1e-6f, 0.0f, -1e-3f, -0.5f};
    Rng rng(97);
    int checked = 0;
    float worst = 0;
    for (int v = 0; v < 32; ++v) {
        Stack s;
        s.base = Spectrum(1);
        s.roughness = v % 2 ? 1.0f : 0.0f;
        s.coat = 1, s.coat_roughness = v / 2 % 2 ? 1.0f : 0.0f;
        s.sheen = v / 4 % 2 ? Spectrum(1) : Spectrum(0);
        s.sheen_roughness = v / 2 % 2 ? 0.0f : 1.0f;
        s.coat_normal = v / 8 % 2 ? kTilted : Vec3(0, 0, 1);
        s.transmission = v / 16 ? 1.0f : 0.0f;
        const GltfBsdf bsdf = make(s);
        for (float cos_o : cosines) {
            const Vec3 wo = spherical_direction(cos_o, 0.7f);
            for (int i = 0; i < 100; ++i) {
                const float cos_i = i < 7 ? cosines[i] : 2 * rng.next_float() - 1;
                const Vec3 wi = spherical_direction(cos_i, 6.28318f * rng.next_float());
                for (Transport mode : {Transport::Radiance, Transport::Importance}) {
                    ASSERT_TRUE(finite_nonneg(bsdf.eval(wo, wi, mode))) << describe(s, wo);
                    const float pdf = bsdf.pdf(wo, wi, mode);
                    ASSERT_TRUE(std::isfinite(pdf) && pdf >= 0) << describe(s, wo);
                }
            }
            const int n = 20000;
            double sum = 0, sum2 = 0;
            for (int i = 0; i < n; ++i) {
                const auto r =
                    bsdf.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()},
                                Transport::Radiance);
                if (!r) continue;
                ASSERT_TRUE(finite_nonneg(r->weight()) && r->pdf > 0) << describe(s, wo);
                ASSERT_NEAR(length(r->wi), 1.0f, 1e-4f) << describe(s, wo);
                // Refracted radiance carries 1/eta^2, which is not energy.
                if (r->eta != 1) continue;
                sum += r->weight().y;
                sum2 += r->weight().y * r->weight().y;
            }
            const double albedo = sum / n;
            const double se = std::sqrt(std::max(0.0, sum2 / n - albedo * albedo) / n);
            // 3 sigma and the tables' interpolation error.
            EXPECT_LE(albedo, 1 + 3 * se + 2e-3) << describe(s, wo) << ": +- " << se;
            worst = std::max(worst, float(albedo));
            ++checked;
        }
    }
    std::printf("GltfBsdf extremes: %d cases, largest albedo %.4f\n", checked, worst);
}

TEST(GltfBsdf, TiltedCoatImportanceIsTheAdjoint) {
    Stack s;
    s.coat = 1, s.coat_roughness = 0.4f, s.coat_normal = kTilted, s.sheen = Spectrum(0.5f);
    const GltfBsdf bsdf = make(s);
    Rng rng(95);
    for (int i = 0; i < 500; ++i) {
        const Vec3 wo = test::random_direction(rng, 0.01f), wi = test::random_direction(rng, 0.01f);
        const Spectrum a = bsdf.eval(wo, wi, Transport::Importance);
        const Spectrum b = bsdf.eval(wi, wo, Transport::Radiance);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-5f * std::max(b[k], 1e-3f));
    }
}

TEST(GltfBsdf, CoatFollowsItsOwnNormal) {
    // A mirror coat tilted away from the base normal reflects about its own normal.
    const Vec3 n = kTilted;
    const ClearcoatLobe coat(1, 0, n, MicrofacetType::Ggx);
    MetalRoughParams p;
    p.metallic = 1;
    const GltfBsdf bsdf(MetalRoughBsdf(p), {}, coat);
    ASSERT_TRUE(bsdf.has_specular());
    const Vec3 wo = spherical_direction(0.9f, 0.3f);
    bool found = false;
    for (float u_lobe = 0; u_lobe < 1; u_lobe += 0.01f) {
        const auto s = bsdf.sample(wo, u_lobe, {0.5f, 0.5f}, Transport::Radiance);
        if (!s || !s->is_specular()) continue;
        found = true;
        const Vec3 expected = reflect(wo, n);
        EXPECT_NEAR(s->wi.x, expected.x, 1e-5f);
        EXPECT_NEAR(s->wi.y, expected.y, 1e-5f);
        EXPECT_NEAR(s->wi.z, expected.z, 1e-5f);
        // Its weight is c F(wo . n) over the lobe's probability.
        const float F = 0.04f + 0.96f * std::pow(1 - dot(wo, n), 5.0f);
        EXPECT_NEAR(s->weight().x * s->pdf, F, 1e-5f);
    }
    EXPECT_TRUE(found);
}

}  // namespace
}  // namespace penumbra
