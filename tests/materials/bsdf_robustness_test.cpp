// Every BSDF model at grazing and below-the-surface directions and at roughness extremes
// (alpha 1e-4 to 1): eval, pdf and sample stay finite and non-negative, directional
// albedo stays <= 1 for the energy-conserving models, the narrowest lobes still pass
// their chi-square test, and alpha -> 0 converges to the mirror.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "core/sampling/rng.h"
#include "materials/lobes/conductor.h"
#include "materials/lobes/cook_torrance.h"
#include "materials/lobes/dielectric.h"
#include "materials/lobes/lambertian.h"
#include "materials/lobes/oren_nayar.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const float kAlphas[] = {1e-4f, 1e-3f, 1e-2f, 0.1f, 0.5f, 1.0f};
// n.v from straight on to exactly grazing, and below the surface (wo.z < 0).
const float kCosines[] = {1.0f, 0.3f, 1e-2f, 1e-4f, 1e-6f, 0.0f, -1e-6f, -1e-3f, -0.5f, -1.0f};

struct Model {
    std::string name;
    std::unique_ptr<Bsdf> bsdf;
    bool conserves = true;  // directional albedo <= 1
};

std::vector<Model> models() {
    std::vector<Model> m;
    m.push_back({"lambertian", std::make_unique<LambertianBsdf>(Spectrum(1))});
    m.push_back({"oren-nayar", std::make_unique<OrenNayarBsdf>(Spectrum(1), 0.5f)});
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
        const std::string t = type == MicrofacetType::Ggx ? "ggx" : "beckmann";
        for (float alpha : kAlphas) {
            const std::string a = " alpha " + std::to_string(alpha);
            m.push_back({"conductor " + t + a,
                         std::make_unique<ConductorBsdf>(Metal::Aluminium, type, alpha)});
            DielectricParams d;
            d.alpha = alpha;
            d.distribution = type;
            m.push_back({"dielectric " + t + a, std::make_unique<DielectricBsdf>(d)});
            CookTorranceParams c;
            c.distribution = type;
            c.alpha = alpha;
            m.push_back({"cook-torrance " + t + a, std::make_unique<CookTorranceBsdf>(c)});
        }
    }
    return m;
}

bool finite_nonneg(const Spectrum& s) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(s[c]) || s[c] < 0) return false;
    return true;
}

TEST(BsdfRobustness, GrazingAndBelowTheSurfaceStayFiniteAndConserveEnergy) {
    Rng rng(17);
    int checked = 0;
    float worst_albedo = 0;
    for (const Model& m : models()) {
        for (const float cos_o : kCosines)
            for (const Transport mode : {Transport::Radiance, Transport::Importance}) {
                const Vec3 wo = spherical_direction(cos_o, 0.7f);
                // eval and pdf against random and grazing wi on both sides.
                for (int i = 0; i < 200; ++i) {
                    const float cos_i = i < 20 ? kCosines[i % 10] : 2 * rng.next_float() - 1;
                    const Vec3 wi = spherical_direction(cos_i, 6.28318f * rng.next_float());
                    const Spectrum f = m.bsdf->eval(wo, wi, mode);
                    const float pdf = m.bsdf->pdf(wo, wi, mode);
                    ASSERT_TRUE(finite_nonneg(f)) << m.name << " wo.z " << cos_o << " wi.z " << cos_i;
                    ASSERT_TRUE(std::isfinite(pdf) && pdf >= 0) << m.name << " wo.z " << cos_o;
                }
                // Sampled weights: finite; their mean (the directional albedo) <= 1.
                const int n = 4000;
                double albedo = 0;
                for (int i = 0; i < n; ++i) {
                    const auto s = m.bsdf->sample(wo, rng.next_float(),
                                                  {rng.next_float(), rng.next_float()}, mode);
                    if (!s) continue;
                    ASSERT_TRUE(finite_nonneg(s->f) && std::isfinite(s->pdf) && s->pdf > 0)
                        << m.name << " wo.z " << cos_o;
                    ASSERT_NEAR(length(s->wi), 1.0f, 1e-4f) << m.name << " wo.z " << cos_o;
                    const Spectrum w = s->weight();
                    ASSERT_TRUE(finite_nonneg(w)) << m.name << " wo.z " << cos_o;
                    // Radiance through a refraction is scaled by 1/eta^2 (up to 2.25 for
                    // eta 1.5): that is not energy, so compare in importance mode.
                    if (mode == Transport::Importance || s->eta == 1) albedo += w.y / n;
                }
                if (mode == Transport::Importance && m.conserves) {
                    worst_albedo = std::max(worst_albedo, float(albedo));
                    // 4000 samples of weights <= ~1: 3 sigma is below 0.02.
                    EXPECT_LE(albedo, 1.02) << m.name << " wo.z " << cos_o;
                }
                ++checked;
            }
    }
    std::printf("BSDF robustness: %d model x direction x mode cases, largest albedo %.4f\n",
                checked, worst_albedo);
}

// alpha 1e-4 is too narrow to bin over the sphere: the half-vector chi-square bins it
// by its microfacet normal (support/bsdf/bsdf_properties.h), down to grazing wo (cos 0.02),
// where that binning would resolve wi's float grid unless it dithers the samples.
TEST(BsdfRobustness, NarrowestLobesStillFollowTheirPdf) {
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, 12);
    int seed = 900;
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann})
        for (float cos_o : {0.8f, 0.2f, 0.02f}) {
            o.seed = ++seed;
            const ConductorBsdf conductor(Metal::Gold, type, 1e-4f);
            const Vec3 wo = spherical_direction(cos_o, 1.1f);
            const test::Chi2Result r = test::bsdf_chi2_half_vector(conductor, wo, 1e-4f, 0, o);
            EXPECT_TRUE(r.passed) << "conductor " << int(type) << " cos_o " << cos_o << "\n"
                                  << r.report;
            DielectricParams d;
            d.alpha = 1e-4f;
            d.distribution = type;
            const DielectricBsdf dielectric(d);
            o.seed = ++seed;
            const test::Chi2Result rd =
                test::bsdf_chi2_half_vector(dielectric, wo, 1e-4f, d.eta, o);
            EXPECT_TRUE(rd.passed) << "dielectric " << int(type) << " cos_o " << cos_o << "\n"
                                   << rd.report;
        }
}

// As alpha -> 0 a rough conductor's samples gather at the mirror direction and its
// albedo tends to the mirror's Fresnel reflectance.
TEST(BsdfRobustness, RoughnessToZeroConvergesToTheMirror) {
    const float cos_o = 0.4f;
    const Vec3 wo = spherical_direction(cos_o, 0.3f);
    const Vec3 mirror(-wo.x, -wo.y, wo.z);
    const ConductorBsdf smooth(Metal::Copper, MicrofacetType::Ggx, 0);
    const auto ms = smooth.sample(wo, 0.5f, {0.5f, 0.5f}, Transport::Radiance);
    ASSERT_TRUE(ms && ms->is_specular());
    const Spectrum F = ms->weight();
    float prev_spread = 1e30f;
    for (float alpha : {1e-1f, 1e-2f, 1e-3f, 1e-4f}) {
        const ConductorBsdf rough(Metal::Copper, MicrofacetType::Ggx, alpha);
        Rng rng(5);
        double spread = 0;
        Spectrum albedo(0);
        const int n = 20000;
        for (int i = 0; i < n; ++i) {
            const auto s =
                rough.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()},
                             Transport::Radiance);
            if (!s) continue;
            spread += std::acos(std::min(1.0f, dot(s->wi, mirror))) / n;
            albedo += s->weight() / float(n);
        }
        // The angular spread of the lobe is of order alpha (radians): reflection doubles
        // the microfacet normal's deviation, and GGX's mean tan(theta_h) is about alpha.
        EXPECT_LT(spread, 4 * alpha) << alpha;
        EXPECT_LT(spread, prev_spread) << alpha;
        prev_spread = float(spread);
        if (alpha <= 1e-3f) {
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(albedo[c], F[c], 0.01f * F[c]) << alpha;
        }
    }
}

}  // namespace
}  // namespace penumbra
