// KHR_materials_iridescence on the transmission models (DielectricBsdf, the closed
// volume's boundary, and ThinDielectricBsdf, the thin-walled sheet): the film's Fresnel
// F splits reflection (F) from transmission (1 - F) per channel, so that a film that
// absorbs nothing conserves energy in every channel. No film is the film-less BSDF bit for
// bit; sampling follows the pdf; sample, eval and pdf agree; reflection is reciprocal
// and refraction adjoint; the white furnace is 1 where the models lose nothing to
// masking; the glTF transmission mixture samples by its pdf with the film on both of its
// parts (the path-traced lens: film_lens_render_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "materials/lobes/cook_torrance.h"
#include "materials/lobes/dielectric.h"
#include "materials/lobes/fresnel.h"
#include "materials/gltf_transmission_bsdf.h"
#include "materials/lobes/thin_dielectric.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

float mean3(Spectrum s) { return (s.x + s.y + s.z) / 3; }
float spread(Spectrum s) { return max_component(s) - std::min({s.x, s.y, s.z}); }

// A sunglasses-like film: iridescenceIor 1.8, 300 nm, full strength.
DielectricParams film_params(float eta, float alpha, float factor = 1, float thickness = 300,
                             bool above = true) {
    DielectricParams p;
    p.eta = eta;
    p.alpha = alpha;
    p.masking = MaskingModel::SmithCorrelated;
    p.iridescence = factor;
    p.film = ThinFilm{1, 1.8f, thickness};
    p.film_above = above;
    return p;
}

std::string describe(const DielectricParams& p, Vec3 wo) {
    std::ostringstream s;
    s << "eta " << p.eta << ", alpha " << p.alpha << ", film " << p.iridescence << " x "
      << p.film.thickness << " nm (ior " << p.film.ior << ", " << (p.film_above ? "above" : "below")
      << "), wo.z " << wo.z;
    return s.str();
}

TEST(FilmInterface, Limits) {
    // Factor 0 is the bare interface; from outside, the film at full strength is the
    // film's reflectance over the base's f0.
    const ThinFilm film{1, 1.8f, 300};
    EXPECT_EQ(film_interface_reflectance(film, 0, 1.5f, 0.7f, 0.25f), Spectrum(0.25f));
    const Spectrum full = film_interface_reflectance(film, 1, 1.5f, 0.7f, 0.25f);
    const Spectrum alone = thin_film_reflectance(film, Spectrum(0.04f), 0.7f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(full[c], alone[c], 1e-7f);  // F + (f - F) 1
    // Snell's law from inside glass: sin_out = 1.5 sin_in; beyond 1/1.5 nothing leaves.
    EXPECT_NEAR(film_outside_cos(0.9f, 1.5f), std::sqrt(1 - 2.25f * (1 - 0.81f)), 1e-6f);
    EXPECT_EQ(film_outside_cos(0.5f, 1.5f), -1.0f);
    EXPECT_EQ(film_outside_cos(-1.0f, 1.5f), 1.0f);
}

TEST(DielectricFilm, NoFilmIsTodaysBsdf) {
    // Factor 0, or a film of thickness 0, leaves both models as without the extension:
    // the same values and samples, bit for bit.
    Rng rng(15);
    for (int i = 0; i < 300; ++i) {
        const float alpha = i % 4 == 0 ? 0.0f : rng.next_float();
        const float eta = i % 3 ? 1.5f : 1 / 1.33f;
        DielectricParams plain = film_params(eta, alpha);
        plain.iridescence = 0;
        plain.film = ThinFilm{};
        const DielectricParams off = film_params(eta, alpha, 0),
                               thin = film_params(eta, alpha, 1, 0);
        const Vec3 wo = test::random_direction(rng, 0.01f, i % 5 == 0);
        const Vec3 wi = test::random_direction(rng, 0.01f, i % 2 == 0);
        const float u = rng.next_float();
        const Vec2 u2(rng.next_float(), rng.next_float());
        for (const DielectricParams* q : {&off, &thin}) {
            const DielectricBsdf a(plain), b(*q);
            const ThinDielectricBsdf c(plain), d(*q);
            for (Transport mode : {Transport::Radiance, Transport::Importance}) {
                EXPECT_EQ(a.eval(wo, wi, mode), b.eval(wo, wi, mode));
                EXPECT_EQ(a.pdf(wo, wi, mode), b.pdf(wo, wi, mode));
                EXPECT_EQ(c.eval(wo, wi, mode), d.eval(wo, wi, mode));
                EXPECT_EQ(c.pdf(wo, wi, mode), d.pdf(wo, wi, mode));
                const auto sa = a.sample(wo, u, u2, mode), sb = b.sample(wo, u, u2, mode);
                ASSERT_EQ(bool(sa), bool(sb));
                if (sa) {
                    EXPECT_EQ(sa->f, sb->f);
                }
                const auto sc = c.sample(wo, u, u2, mode), sd = d.sample(wo, u, u2, mode);
                ASSERT_EQ(bool(sc), bool(sd));
                if (sc) {
                    EXPECT_EQ(sc->f, sd->f);
                }
            }
        }
    }
}

// The smooth models' two Dirac lobes at wo: what each carries (weight times its
// probability, so f |cos| per lobe) and the probability of reflection.
struct Split {
    Spectrum R, T;
    float p_reflect = 0;
};
Split smooth_split(const Bsdf& bsdf, Vec3 wo) {
    Split s;
    const auto r = bsdf.sample(wo, 0, {0.5f, 0.5f}, Transport::Importance);
    const auto t = bsdf.sample(wo, 0x1.fffffep-1f, {0.5f, 0.5f}, Transport::Importance);
    if (r && r->wi.z * wo.z > 0) {
        s.R = r->weight() * r->pdf;
        s.p_reflect = r->pdf;
    }
    if (t && t->wi.z * wo.z < 0) s.T = t->weight() * t->pdf;
    return s;
}

TEST(DielectricFilm, SmoothSplitsEachChannel) {
    // Reflection carries F, transmission 1 - F, channel by channel (importance: no eta^2),
    // and reflection is chosen with probability mean(F). From inside glass (the film on
    // the far side) the film's F is the outside's at the refracted angle, and beyond the
    // critical angle everything reflects.
    for (bool above : {true, false})
        for (float cos_o : {1.0f, 0.6f, 0.1f, -0.95f, -0.5f}) {
            const DielectricParams p = film_params(above ? 1.5f : 1 / 1.5f, 0, 1, 300, above);
            const DielectricBsdf bsdf(p);
            ASSERT_TRUE(bsdf.has_specular());
            const Vec3 wo = spherical_direction(cos_o, 0.3f);
            const Split s = smooth_split(bsdf, wo);
            const bool outside = (cos_o > 0) == above;
            const float c_out = outside ? std::abs(cos_o) : film_outside_cos(cos_o, 1.5f);
            const Spectrum F = c_out < 0
                                   ? Spectrum(1)
                                   : film_interface_reflectance(p.film, 1, 1.5f, c_out,
                                                                fresnel_dielectric(cos_o, p.eta));
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(s.R[c], F[c], 2e-6f) << describe(p, wo);
                EXPECT_NEAR(s.T[c], 1 - F[c], 2e-6f) << describe(p, wo);
            }
            EXPECT_NEAR(s.p_reflect, mean3(F), 1e-6f) << describe(p, wo);
        }
    // The film colours a white interface: at normal incidence the reflection is no
    // longer grey (bare glass: 0.04 in every channel), nor the transmission.
    const Split s = smooth_split(DielectricBsdf(film_params(1.5f, 0)), Vec3(0, 0, 1));
    EXPECT_GT(spread(s.R), 0.05f);
    EXPECT_NEAR(spread(s.T), spread(s.R), 1e-6f);
}

TEST(DielectricFilm, IndexMatchedReflectsTheFilmOnly) {
    // The sunglasses' lens: IOR 1 under the film. The bare interface reflects nothing, so
    // all reflection is the film's, over a base of IOR 1 (f0 = 0).
    for (float cos_o : {1.0f, 0.4f}) {
        const Vec3 wo = spherical_direction(cos_o, 0.5f);
        const Spectrum F = thin_film_reflectance(ThinFilm{1, 1.8f, 300}, Spectrum(0), cos_o);
        const Split vol = smooth_split(DielectricBsdf(film_params(1.0f, 0.3f)), wo);
        const Split sheet = smooth_split(ThinDielectricBsdf(film_params(1.0f, 0)), wo);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(vol.R[c], F[c], 1e-6f);
            EXPECT_NEAR(vol.T[c], 1 - F[c], 1e-6f);
            EXPECT_NEAR(sheet.R[c], F[c], 1e-6f);
            EXPECT_NEAR(sheet.T[c], 1 - F[c], 1e-6f);
        }
        EXPECT_GT(max_component(F), 0.1f);
    }
}

TEST(ThinDielectricFilm, SheetSumsTheFilmFaceAndTheBareFace) {
    // R' = (R1 + R - 2 R1 R) / (1 - R1 R): the film's face R1, the bare face R; with R1 = R
    // the bare sheet's 2R / (1 + R).
    for (float cos_o : {1.0f, 0.5f, 0.05f, -0.7f}) {
        const DielectricParams p = film_params(1.5f, 0);
        const Vec3 wo = spherical_direction(cos_o, 1.0f);
        const float R = fresnel_dielectric(std::abs(cos_o), 1.5f);
        const Spectrum R1 = film_interface_reflectance(p.film, 1, 1.5f, std::abs(cos_o), R);
        const Spectrum Rs = ThinDielectricBsdf(p).reflectance(cos_o);
        const Split s = smooth_split(ThinDielectricBsdf(p), wo);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(Rs[c], (R1[c] + R - 2 * R1[c] * R) / (1 - R1[c] * R), 1e-6f);
            EXPECT_NEAR(s.R[c], Rs[c], 2e-6f);
            EXPECT_NEAR(s.T[c], 1 - Rs[c], 2e-6f);
        }
    }
}

TEST(DielectricFilm, SmoothWhiteFurnace) {
    // Importance albedo (light arriving from wo) of a white, non-absorbing filmed
    // interface: per channel a sample weighs F / mean(F) or (1 - F) / (1 - mean(F)), whose
    // mean is exactly 1. Within 4 standard errors of the estimate.
    for (bool above : {true, false})
        for (float cos_o : {1.0f, 0.5f, 0.05f, -0.3f, -0.95f}) {
            const Vec3 wo = spherical_direction(cos_o, 2.0f);
            const DielectricParams p = film_params(above ? 1.5f : 1 / 1.5f, 0, 1, 300, above);
            const DielectricBsdf boundary(p);
            const ThinDielectricBsdf sheet(p);
            for (const Bsdf* bsdf :
                 {static_cast<const Bsdf*>(&boundary), static_cast<const Bsdf*>(&sheet)}) {
                const test::AlbedoEstimate a =
                    test::directional_albedo(*bsdf, wo, 20000, 7, Transport::Importance);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(a.mean[c], 1.0f, 4 * a.std_error[c] + 1e-5f) << describe(p, wo);
            }
        }
}

TEST(DielectricFilm, RoughSamplesFollowThePdf) {
    // The whole sphere, from outside and from inside (cos -0.6: beyond the critical angle
    // but for rough facets), the film above and below; alpha 1e-3 by half vector.
    const float alphas[] = {1e-3f, 0.2f, 1.0f};
    const float cos_os[] = {0.9f, 0.05f, -0.9f, -0.6f};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, std::size(alphas) * std::size(cos_os));
    int seed = 700;
    for (float alpha : alphas)
        for (float cos_o : cos_os) {
            const bool above = seed % 2 == 0;
            const DielectricParams p =
                film_params(above ? 1.5f : 1 / 1.5f, alpha, 0.8f, 150 + 50 * (seed % 7), above);
            const DielectricBsdf bsdf(p);
            const Vec3 wo = spherical_direction(cos_o, 0.4f);
            o.seed = ++seed;
            const test::Chi2Result r = alpha < 0.01f
                                           ? test::bsdf_chi2_half_vector(bsdf, wo, alpha, p.eta, o)
                                           : test::bsdf_chi2_sphere(bsdf, wo, o);
            EXPECT_TRUE(r.passed) << describe(p, wo) << "\n" << r.report;
            const double lost = double(r.lost) / r.samples;
            EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 2e-4)
                << describe(p, wo);
        }
}

TEST(ThinDielectricFilm, RoughSamplesFollowThePdf) {
    const float alphas[] = {0.05f, 0.3f, 1.0f};
    const float cos_os[] = {0.9f, 0.05f, -0.7f};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, std::size(alphas) * std::size(cos_os));
    int seed = 750;
    for (float alpha : alphas)
        for (float cos_o : cos_os) {
            const DielectricParams p = film_params(seed % 2 ? 1.5f : 1.0f, alpha, 1, 300);
            const ThinDielectricBsdf bsdf(p);
            const Vec3 wo = spherical_direction(cos_o, 0.4f);
            o.seed = ++seed;
            const test::Chi2Result r = test::bsdf_chi2_sphere(bsdf, wo, o);
            EXPECT_TRUE(r.passed) << describe(p, wo) << "\n" << r.report;
        }
}

TEST(DielectricFilm, RoughAgreementReciprocityAndAdjoint) {
    Rng rng(19);
    for (int i = 0; i < 120; ++i) {
        const bool above = i % 2 == 0;
        const float eta = i % 3 ? 1.5f : 1.33f;
        DielectricParams p = film_params(above ? eta : 1 / eta, 0.02f + rng.next_float(),
                                         rng.next_float(), 100 + 700 * rng.next_float(), above);
        p.transmittance = {0.9f, 0.5f, 0.2f};
        const DielectricBsdf bsdf(p);
        const ThinDielectricBsdf sheet(p);
        const Vec3 wo = test::random_direction(rng, 0.02f, i % 5 == 0);
        const Transport mode = i % 4 < 2 ? Transport::Radiance : Transport::Importance;
        EXPECT_EQ(test::check_sample_agreement(bsdf, wo, 50, i, mode), "") << describe(p, wo);
        EXPECT_EQ(test::check_sample_agreement(sheet, wo, 50, i, mode), "") << describe(p, wo);
        if (i % 10 == 0) {
            EXPECT_EQ(test::check_reciprocity(bsdf, 100, i), "") << describe(p, wo);
            EXPECT_EQ(test::check_reciprocity(sheet, 100, i), "") << describe(p, wo);
        }
        // Refraction: the importance BSDF is the radiance one with its arguments swapped
        // (Veach 1997, eq. 5.20): the film's F is the same from both sides.
        p.transmittance = Spectrum(1);
        const DielectricBsdf white(p);
        const Vec3 a = test::random_direction(rng, 0.02f),
                   b = test::random_direction(rng, 0.02f, true);
        const Spectrum imp = white.eval(a, b, Transport::Importance);
        const Spectrum rad = white.eval(b, a, Transport::Radiance);
        for (int c = 0; c < 3; ++c) {
            if (rad[c] < 1e-30f) continue;  // denormals carry no relative precision
            EXPECT_NEAR(imp[c], rad[c], 2e-4f * std::max(imp[c], rad[c])) << describe(p, a);
        }
    }
}

TEST(DielectricFilm, RoughWhiteFurnace) {
    // Never above 1 in any channel; nearly smooth and head-on, within what masking loses
    // (as the bare interface, dielectric_test.cpp) of 1 in every channel.
    for (float alpha : {1e-3f, 0.2f, 0.6f, 1.0f})
        for (float cos_o : {1.0f, 0.3f, 0.05f, -0.8f, -0.1f}) {
            const DielectricParams p = film_params(1.5f, alpha, 1, 300, cos_o > 0.5f);
            const Vec3 wo = spherical_direction(cos_o, 0.5f);
            const test::AlbedoEstimate a =
                test::directional_albedo(DielectricBsdf(p), wo, 20000, 12, Transport::Importance);
            for (int c = 0; c < 3; ++c) {
                EXPECT_LE(a.mean[c], 1 + 3 * a.std_error[c] + 1e-5f) << describe(p, wo);
                if (alpha == 1e-3f && std::abs(cos_o) > 0.5f) {
                    EXPECT_NEAR(a.mean[c], 1.0f, 1e-3f + 4 * a.std_error[c]) << describe(p, wo);
                }
            }
        }
}

TEST(ThinDielectricFilm, ReflectionPlusTransmissionIsTheWhiteMirrorLobe) {
    // For the same microfacet, reflection and transmission together carry (R' + T') =
    // 1 times the white mirror lobe (Cook-Torrance with F = 1), channel by channel: the
    // filmed sheet loses exactly what single-scattering microfacets lose.
    for (float alpha : {1e-3f, 0.2f, 0.6f, 1.0f})
        for (float cos_o : {1.0f, 0.4f, 0.03f}) {
            const DielectricParams p = film_params(1.5f, alpha);
            const ThinDielectricBsdf sheet(p);
            CookTorranceParams cp;
            cp.alpha = alpha;
            const CookTorranceBsdf mirror(cp);
            const Vec3 wo = spherical_direction(cos_o, 1.1f);
            Rng rng(78);
            for (int k = 0; k < 200; ++k) {
                const Vec2 u(rng.next_float(), rng.next_float());
                const auto m = mirror.sample(wo, 0.5f, u, Transport::Radiance);
                const auto r = sheet.sample(wo, 0, u, Transport::Radiance);
                const auto t = sheet.sample(wo, 0x1.fffffep-1f, u, Transport::Radiance);
                ASSERT_EQ(bool(m), bool(r)) << describe(p, wo);
                ASSERT_EQ(bool(m), bool(t)) << describe(p, wo);
                if (!m) continue;
                // pdf(r) + pdf(t) is the lobe's density at the microfacet.
                const Spectrum both =
                    (r->f * std::abs(r->wi.z) + t->f * std::abs(t->wi.z)) / (r->pdf + t->pdf);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(both[c], m->weight()[c], 2e-4f * m->weight()[c]) << describe(p, wo);
            }
        }
}

TEST(GltfTransmissionFilm, BothPartsTakeTheFilm) {
    // KHR_materials_transmission over part of the base: the opaque glTF BRDF and the
    // dielectric each carry the film; the mixture still samples by its pdf, agrees with
    // eval, and a white non-metal never reflects plus transmits more than 1.
    int seed = 800;
    for (bool thin : {false, true})
        for (float alpha : {0.0f, 0.09f, 0.5f}) {
            MetalRoughParams p;
            p.base_color = Spectrum(1);
            p.metallic = 0;
            p.alpha = alpha;
            p.iridescence = 1;
            p.film = ThinFilm{1, 1.8f, 300};
            const DielectricParams d = film_params(1.5f, alpha);
            const GltfTransmissionBsdf bsdf(p, 0.6f, d, thin);
            for (float cos_o : {0.9f, 0.2f}) {
                const Vec3 wo = spherical_direction(cos_o, 0.3f);
                std::ostringstream what;
                what << (thin ? "thin-walled" : "volume") << ", alpha " << alpha << ", wo.z "
                     << cos_o;
                EXPECT_EQ(test::check_sample_agreement(bsdf, wo, 100, ++seed, Transport::Radiance),
                          "")
                    << what.str();
                if (alpha > 0) {
                    test::BsdfChi2Options o;
                    o.samples = 100000;
                    o.seed = seed;
                    o.significance = test::sidak_significance(0.01, 8);
                    const test::Chi2Result r = test::bsdf_chi2_sphere(bsdf, wo, o);
                    EXPECT_TRUE(r.passed) << what.str() << "\n" << r.report;
                }
                const test::AlbedoEstimate a =
                    test::directional_albedo(bsdf, wo, 20000, seed, Transport::Importance);
                for (int c = 0; c < 3; ++c) {
                    // The opaque part's film bound (thin_film_test.cpp) adds no gain.
                    EXPECT_LE(a.mean[c], 1 + 4 * a.std_error[c] + 1e-5f) << what.str();
                }
            }
        }
}

}  // namespace
}  // namespace penumbra
