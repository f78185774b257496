// Fresnel terms against closed forms: normal incidence, Brewster's angle, the 45-degree
// identity Rp = Rs^2, total internal reflection, Stokes reciprocity, and the conductor
// equations at normal incidence and in the dielectric limit k = 0.
#include "materials/lobes/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

const float kEtas[] = {1.2f, 1.33f, 1.5f, 2.4f};

TEST(FresnelDielectric, NormalIncidence) {
    for (float eta : kEtas) {
        const float expected = ((eta - 1) / (eta + 1)) * ((eta - 1) / (eta + 1));
        EXPECT_NEAR(fresnel_dielectric(1, eta), expected, 1e-6f);
        EXPECT_NEAR(fresnel_dielectric(-1, eta), expected, 1e-6f);  // from inside
        EXPECT_NEAR(f0_from_ior(eta), expected, 1e-6f);
        EXPECT_NEAR(fresnel_dielectric(1, 1 / eta), expected, 1e-6f);
    }
    EXPECT_NEAR(fresnel_dielectric(0.3f, 1), 0.0f, 1e-12f);  // index-matched: no interface
}

TEST(FresnelDielectric, BrewsterAngleReflectsNoPPolarizedLight) {
    for (float eta : kEtas) {
        const float theta_b = std::atan(eta);
        const PolarizedReflectance r = fresnel_dielectric_polarized(std::cos(theta_b), eta);
        EXPECT_NEAR(r.rp, 0.0f, 1e-7f) << "eta " << eta;
        EXPECT_GT(r.rs, 0.01f);
        EXPECT_FLOAT_EQ(fresnel_dielectric(std::cos(theta_b), eta), 0.5f * r.rs);
        // Brewster's angle from inside: tan = 1 / eta.
        const PolarizedReflectance inside =
            fresnel_dielectric_polarized(-std::cos(std::atan(1 / eta)), eta);
        EXPECT_NEAR(inside.rp, 0.0f, 1e-7f) << "eta " << eta;
    }
}

TEST(FresnelDielectric, FortyFiveDegreesGivesRpEqualToRsSquared) {
    // A classic identity of the Fresnel equations at 45 degrees; for eta 1.5 the values
    // are Rs = 0.0920 and Rp = 0.00847 (Hecht, Optics, sec. 4.6).
    for (float eta : kEtas) {
        const PolarizedReflectance r = fresnel_dielectric_polarized(std::sqrt(0.5f), eta);
        EXPECT_NEAR(r.rp, r.rs * r.rs, 1e-6f) << "eta " << eta;
    }
    const PolarizedReflectance r = fresnel_dielectric_polarized(std::sqrt(0.5f), 1.5f);
    EXPECT_NEAR(r.rs, 0.09201f, 1e-5f);
    EXPECT_NEAR(r.rp, 0.008466f, 1e-6f);
}

TEST(FresnelDielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
    for (float eta : kEtas) {
        const float cos_c = std::sqrt(1 - 1 / (eta * eta));  // sin(theta_c) = 1 / eta
        EXPECT_EQ(fresnel_dielectric(-cos_c * 0.999f, eta), 1.0f) << "eta " << eta;
        EXPECT_EQ(fresnel_dielectric(-0.01f, eta), 1.0f);
        EXPECT_LT(fresnel_dielectric(-std::min(1.0f, cos_c * 1.01f), eta), 1.0f);
        // Outside there is no critical angle, but grazing light is all reflected.
        EXPECT_LT(fresnel_dielectric(0.01f, eta), 1.0f);
        EXPECT_NEAR(fresnel_dielectric(1e-6f, eta), 1.0f, 1e-4f);
        EXPECT_FALSE(refract(Vec3(std::sqrt(1 - 0.01f * cos_c * cos_c), 0, 0.1f * cos_c),
                             Vec3(0, 0, 1), 1 / eta));
    }
}

TEST(FresnelDielectric, IsTheSameBothWaysThroughTheInterface) {
    // Stokes: R(theta_i) outside equals R(theta_t) inside for the refracted angle.
    for (float eta : kEtas)
        for (float cos_i = 0.05f; cos_i <= 1; cos_i += 0.05f) {
            const Vec3 wi(std::sqrt(1 - cos_i * cos_i), 0, cos_i);
            const std::optional<Vec3> wt = refract(wi, Vec3(0, 0, 1), eta);
            ASSERT_TRUE(wt);
            EXPECT_NEAR(length(*wt), 1.0f, 1e-6f);
            EXPECT_NEAR(wi.x, -eta * wt->x, 1e-6f);  // Snell: sin_i = eta sin_t
            EXPECT_LT(wt->z, 0.0f);
            EXPECT_NEAR(fresnel_dielectric(cos_i, eta), fresnel_dielectric(wt->z, eta), 1e-5f);
            // Refracting back returns the original direction.
            const std::optional<Vec3> back = refract(*wt, Vec3(0, 0, -1), 1 / eta);
            ASSERT_TRUE(back);
            EXPECT_NEAR(back->x, wi.x, 1e-5f);
            EXPECT_NEAR(back->z, wi.z, 1e-5f);
        }
}

TEST(FresnelConductor, GoldAtNormalIncidence) {
    const ComplexIor gold = metal_ior(Metal::Gold);
    const Spectrum F = fresnel_conductor(1, gold.eta, gold.k);
    for (int c = 0; c < 3; ++c) {
        const float n = gold.eta[c], k = gold.k[c];
        const float expected = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
        EXPECT_NEAR(F[c], expected, 1e-6f) << "channel " << c;
    }
    // Gold is yellow: red reflects most, blue least.
    EXPECT_GT(F.x, F.y);
    EXPECT_GT(F.y, F.z);
}

TEST(FresnelConductor, ReducesToTheDielectricWithoutAbsorption) {
    for (float eta : kEtas)
        for (float cos_i = 0.02f; cos_i <= 1; cos_i += 0.07f)
            EXPECT_NEAR(fresnel_complex(cos_i, eta, 0), fresnel_dielectric(cos_i, eta), 1e-5f)
                << "eta " << eta << ", cos " << cos_i;
}

TEST(FresnelConductor, NamedMetalsAreBoundedAndGrazingReflectsAll) {
    for (Metal m : {Metal::Gold, Metal::Copper, Metal::Aluminium, Metal::Silver}) {
        const ComplexIor ior = metal_ior(m);
        for (float cos_i = 0; cos_i <= 1; cos_i += 0.01f) {
            const Spectrum F = fresnel_conductor(cos_i, ior.eta, ior.k);
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(F[c], 0.0f);
                EXPECT_LE(F[c], 1.0f);
            }
        }
        const Spectrum grazing = fresnel_conductor(0, ior.eta, ior.k);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(grazing[c], 1.0f, 1e-6f);
        // Metals reflect most of the light head-on (aluminium and silver > 0.9).
        EXPECT_GT(min_component(fresnel_conductor(1, ior.eta, ior.k)),
                  m == Metal::Gold || m == Metal::Copper ? 0.3f : 0.9f);
    }
}

TEST(Fresnel, ValueTypeDispatches) {
    const ComplexIor cu = metal_ior(Metal::Copper);
    for (float c : {0.1f, 0.5f, 1.0f}) {
        EXPECT_EQ(Fresnel::schlick(Spectrum(0.04f), 0.8f).eval(c),
                  fresnel_schlick(Spectrum(0.04f), 0.8f, c));
        EXPECT_EQ(Fresnel::dielectric(1.33f).eval(c), Spectrum(fresnel_dielectric(c, 1.33f)));
        EXPECT_EQ(Fresnel::conductor(cu).eval(c), fresnel_conductor(c, cu.eta, cu.k));
    }
    EXPECT_EQ(Fresnel().eval(0.3f), Spectrum(1));  // the default reflects everything
}

}  // namespace
}  // namespace penumbra
