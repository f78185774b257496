// Microfacet distributions shared by all rough models, in the local frame (z = macro
// normal; alpha_x along x, alpha_y along y, equal when isotropic): GGX and Beckmann with
// Smith masking and visible-normal sampling (Walter 2007; Heitz 2014, 2018; Jakob 2014);
// MicrofacetDistribution picks one.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math/vec.h"
#include "core/math/portable_math.h"

namespace penumbra {

// Anisotropic GGX and Beckmann are their alpha-1 versions with the microsurface stretched
// by (alpha_x, alpha_y) (Heitz 2014, "Understanding the Masking-Shadowing Function", sec.
// 5.3): Lambda(w) is the isotropic one at the projected roughness
// sqrt(alpha_x^2 cos^2 phi + alpha_y^2 sin^2 phi), and visible normals are sampled in the
// stretched space. The isotropic case keeps its own expressions (bitwise as before).
class GgxDistribution {
public:
    explicit GgxDistribution(float alpha) : GgxDistribution(alpha, alpha) {}
    GgxDistribution(float alpha_x, float alpha_y)
        : m_alpha(std::max(alpha_x, 1e-7f)), m_alpha_y(std::max(alpha_y, 1e-7f)) {}
    float alpha() const { return m_alpha; }  // alpha_x
    float alpha_x() const { return m_alpha; }
    float alpha_y() const { return m_alpha_y; }

    // Normal distribution D(h), normalized so that the integral of D(h) cos(theta_h)
    // over the hemisphere is 1.
    float D(Vec3 h) const {
        if (h.z <= 0) return 0;
        if (m_alpha != m_alpha_y) {
            // 1 / (pi ax ay (x^2/ax^2 + y^2/ay^2 + z^2)^2) (Heitz 2014, eq. 85).
            const float x = h.x / m_alpha, y = h.y / m_alpha_y;
            const float s = h.z * h.z + (x * x + y * y);
            return 1 / (kPi * m_alpha * m_alpha_y * s * s);
        }
        // cos^2 (a^2 - 1) + 1 as cos^2 a^2 + sin^2, with sin^2 from x and y: near the
        // normal, 1 - cos^2 is a few float ulps and cancels catastrophically once a^2 is
        // small (1e-5 at roughness 0.05).
        const float a2 = m_alpha * m_alpha;
        const float denom = h.z * h.z * a2 + (h.x * h.x + h.y * h.y);
        return a2 / (kPi * denom * denom);
    }
    // Smith's Lambda(w).
    float lambda(Vec3 w) const {
        const float cos2 = w.z * w.z;
        if (cos2 <= 0) return 0;
        if (m_alpha != m_alpha_y) {
            // alpha(phi)^2 tan^2 = (ax^2 x^2 + ay^2 y^2) / z^2 (Heitz 2014, eq. 86).
            const float x = m_alpha * w.x, y = m_alpha_y * w.y;
            return 0.5f * (-1 + std::sqrt(1 + (x * x + y * y) / cos2));
        }
        const float tan2 = std::max(0.0f, 1 - cos2) / cos2;
        return 0.5f * (-1 + std::sqrt(1 + m_alpha * m_alpha * tan2));
    }
    float G1(Vec3 w) const { return 1 / (1 + lambda(w)); }
    // Height-correlated masking-shadowing (Heitz 2014, eq. 99).
    float G(Vec3 wo, Vec3 wi) const { return 1 / (1 + lambda(wo) + lambda(wi)); }

    // Density of visible normals seen from wo (wo.z > 0): G1(wo) max(0, wo.h) D(h) / wo.z.
    float pdf_visible(Vec3 wo, Vec3 h) const {
        const float woh = dot(wo, h);
        if (woh <= 0 || wo.z <= 0) return 0;
        return G1(wo) * woh * D(h) / wo.z;
    }
    // Samples a visible normal for wo (wo.z > 0), Heitz 2018 ("Sampling the GGX
    // Distribution of Visible Normals", listing 1).
    Vec3 sample_visible(Vec3 wo, Vec2 u) const {
        const Vec3 vh = normalize(Vec3(m_alpha * wo.x, m_alpha_y * wo.y, wo.z));
        const float lensq = vh.x * vh.x + vh.y * vh.y;
        const Vec3 t1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
        const Vec3 t2 = cross(vh, t1);
        const float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
        const float p1 = r * portable_cos(phi);
        const float s = 0.5f * (1 + vh.z);
        const float p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * r * portable_sin(phi);
        const Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2));
        return normalize(Vec3(m_alpha * nh.x, m_alpha_y * nh.y, std::max(1e-6f, nh.z)));
    }
    // Samples D(h) cos(theta_h) (Walter et al. 2007, eq. 35): tan^2 = a^2 u / (1 - u);
    // anisotropic: the alpha-1 slopes scaled by (alpha_x, alpha_y).
    Vec3 sample_D(Vec2 u) const {
        const float t = std::sqrt(u.x / std::max(1 - u.x, 1e-12f));
        const float tan_x = m_alpha * t, tan_y = m_alpha_y * t;
        const float phi = 2 * kPi * u.y;
        return normalize(Vec3(tan_x * portable_cos(phi), tan_y * portable_sin(phi), 1));
    }

private:
    float m_alpha;  // alpha_x
    float m_alpha_y;
};

// Inverse error function: Winitzki's closed-form guess refined by Newton steps on
// std::erf, in double so the tails of the slope distribution keep their shape.
inline double erf_inv(double y) {
    if (!(y > -1)) return -std::numeric_limits<double>::infinity();
    if (!(y < 1)) return std::numeric_limits<double>::infinity();
    const double a = 0.147, l = std::log((1 - y) * (1 + y));
    const double t = 2 / (kPi * a) + 0.5 * l;
    double x = std::copysign(std::sqrt(std::sqrt(t * t - l / a) - t), y);
    for (int i = 0; i < 3; ++i)
        x -= (std::erf(x) - y) * (0.5 * std::sqrt(double(kPi))) * std::exp(x * x);
    return x;
}

class BeckmannDistribution {
public:
    explicit BeckmannDistribution(float alpha) : BeckmannDistribution(alpha, alpha) {}
    BeckmannDistribution(float alpha_x, float alpha_y)
        : m_alpha(std::max(alpha_x, 1e-7f)), m_alpha_y(std::max(alpha_y, 1e-7f)) {}
    float alpha() const { return m_alpha; }  // alpha_x
    float alpha_x() const { return m_alpha; }
    float alpha_y() const { return m_alpha_y; }

    // D(h) = exp(-tan^2 / a^2) / (pi a^2 cos^4) (Cook & Torrance 1982; Walter et al.
    // 2007, eq. 25); tan^2 from x and y, as for GGX, so narrow lobes keep their shape.
    float D(Vec3 h) const {
        if (h.z <= 0) return 0;
        const float cos2 = h.z * h.z;
        if (m_alpha != m_alpha_y) {
            // exp(-(x^2/ax^2 + y^2/ay^2) / z^2) / (pi ax ay cos^4) (Heitz 2014, eq. 82).
            const float x = h.x / m_alpha, y = h.y / m_alpha_y;
            const float e = (x * x + y * y) / cos2;
            if (!(e < 80)) return 0;
            return std::exp(-e) / (kPi * m_alpha * m_alpha_y * cos2 * cos2);
        }
        const float a2 = m_alpha * m_alpha;
        const float tan2 = (h.x * h.x + h.y * h.y) / cos2;
        // Far in the tail exp() is 0 while cos^4 may underflow too: 0, not 0 / 0.
        if (!(tan2 < 80 * a2)) return 0;
        return std::exp(-tan2 / a2) / (kPi * a2 * cos2 * cos2);
    }
    // Exact Smith Lambda (Walter et al. 2007, eq. 27 written as Lambda), with
    // a = 1 / (alpha tan theta); erfc avoids the cancellation of erf(a) - 1.
    float lambda(Vec3 w) const {
        const float sin_theta = std::sqrt(w.x * w.x + w.y * w.y);
        if (sin_theta == 0) return 0;
        // alpha(phi) sin(theta) = sqrt(ax^2 x^2 + ay^2 y^2) when anisotropic.
        const double alpha_sin =
            m_alpha == m_alpha_y
                ? double(m_alpha) * sin_theta
                : std::sqrt(double(m_alpha * w.x) * (m_alpha * w.x) +
                            double(m_alpha_y * w.y) * (m_alpha_y * w.y));
        const double a = std::abs(w.z) / alpha_sin;
        const double l = 0.5 * (std::exp(-a * a) / (a * std::sqrt(double(kPi))) - std::erfc(a));
        return float(std::max(0.0, l));
    }
    float G1(Vec3 w) const { return 1 / (1 + lambda(w)); }
    float G(Vec3 wo, Vec3 wi) const { return 1 / (1 + lambda(wo) + lambda(wi)); }

    float pdf_visible(Vec3 wo, Vec3 h) const {
        const float woh = dot(wo, h);
        if (woh <= 0 || wo.z <= 0) return 0;
        return G1(wo) * woh * D(h) / wo.z;
    }
    // Visible normals for wo (wo.z > 0): stretch to alpha 1, sample the slopes seen from
    // that direction, rotate and unstretch (Heitz & d'Eon 2014, sec. 4). The x slope
    // inverts its CDF numerically in the erf domain (Jakob 2014, "An Improved Visible
    // Normal Sampling Routine for the Beckmann Distribution").
    Vec3 sample_visible(Vec3 wo, Vec2 u) const {
        const Vec3 ws = normalize(Vec3(m_alpha * wo.x, m_alpha_y * wo.y, wo.z));
        const float sin_theta = std::sqrt(ws.x * ws.x + ws.y * ws.y);
        double sx, sy;
        sample_slopes(ws.z, sin_theta, u, sx, sy);
        const float cos_phi = sin_theta > 0 ? ws.x / sin_theta : 1;
        const float sin_phi = sin_theta > 0 ? ws.y / sin_theta : 0;
        const float x = float(cos_phi * sx - sin_phi * sy) * m_alpha;
        const float y = float(sin_phi * sx + cos_phi * sy) * m_alpha_y;
        return normalize(Vec3(-x, -y, 1));
    }
    // Samples D(h) cos(theta_h) (Walter et al. 2007, eq. 28): tan^2 = -a^2 log(1 - u);
    // anisotropic: the alpha-1 slopes scaled by (alpha_x, alpha_y).
    Vec3 sample_D(Vec2 u) const {
        const float t = std::sqrt(-std::log1p(-std::min(u.x, 1 - 1e-7f)));
        const float tan_x = m_alpha * t, tan_y = m_alpha_y * t;
        const float phi = 2 * kPi * u.y;
        return normalize(Vec3(tan_x * portable_cos(phi), tan_y * portable_sin(phi), 1));
    }

private:
    // Slopes of the alpha-1 distribution visible from theta (cos_theta, sin_theta), for a
    // direction at phi = 0. The x slope has density exp(-x^2)(1 - x tan) on x < cot, with
    // CDF proportional to 1 + b + tan / sqrt(pi) exp(-x^2) in b = erf(x); y is an
    // independent normal of variance 1/2.
    static void sample_slopes(float cos_theta, float sin_theta, Vec2 u, double& sx, double& sy) {
        const double inv_sqrt_pi = 1 / std::sqrt(double(kPi));
        const double tan_theta = sin_theta / double(cos_theta);
        const double ux = std::clamp(double(u.x), 1e-9, 1 - 1e-9);
        sy = erf_inv(2 * std::clamp(double(u.y), 1e-9, 1 - 1e-9) - 1);
        if (tan_theta < 1e-7) {  // normal incidence: both slopes are plain normals
            sx = erf_inv(2 * ux - 1);
            return;
        }
        const double cot_theta = 1 / tan_theta;
        double lo = -1, hi = std::erf(cot_theta);
        const double norm =
            1 / (1 + hi + inv_sqrt_pi * tan_theta * std::exp(-cot_theta * cot_theta));
        // Jakob's fitted initial guess, then Newton steps kept inside the bracket.
        const double theta = std::acos(double(cos_theta));
        const double fit = 1 + theta * (-0.876 + theta * (0.4265 - 0.0594 * theta));
        double b = hi - (1 + hi) * std::pow(1 - ux, fit);
        for (int it = 0; it < 30; ++it) {
            if (!(b >= lo && b <= hi)) b = 0.5 * (lo + hi);
            const double x = erf_inv(b);
            const double value = norm * (1 + b + inv_sqrt_pi * tan_theta * std::exp(-x * x)) - ux;
            if (std::abs(value) < 1e-10) break;
            (value > 0 ? hi : lo) = b;
            b -= value / (norm * (1 - x * tan_theta));
        }
        sx = erf_inv(b);
    }

    float m_alpha;  // alpha_x
    float m_alpha_y;
};

enum class MicrofacetType { Ggx, Beckmann };

// Masking-shadowing G(wo, wi, h): Smith height-correlated 1 / (1 + L(wo) + L(wi)) (Heitz
// 2014, eq. 99), Smith separable G1(wo) G1(wi) (Walter et al. 2007, eq. 23), or the
// Cook-Torrance V-cavity min(1, 2 n.h n.v / v.h, 2 n.h n.l / v.h) (Cook & Torrance 1982).
enum class MaskingModel { SmithCorrelated, SmithSeparable, VCavity };

// A distribution chosen at run time: D, G and sampling dispatch on the type.
class MicrofacetDistribution {
public:
    MicrofacetDistribution(MicrofacetType type, float alpha)
        : MicrofacetDistribution(type, alpha, alpha) {}
    MicrofacetDistribution(MicrofacetType type, float alpha_x, float alpha_y)
        : m_type(type), m_alpha(std::max(alpha_x, 1e-7f)), m_alpha_y(std::max(alpha_y, 1e-7f)) {}
    MicrofacetType type() const { return m_type; }
    float alpha() const { return m_alpha; }  // alpha_x
    float alpha_x() const { return m_alpha; }
    float alpha_y() const { return m_alpha_y; }

    float D(Vec3 h) const { return visit([&](const auto& d) { return d.D(h); }); }
    float lambda(Vec3 w) const { return visit([&](const auto& d) { return d.lambda(w); }); }
    float G1(Vec3 w) const { return 1 / (1 + lambda(w)); }
    // Height-correlated Smith, the glTF default.
    float G(Vec3 wo, Vec3 wi) const { return 1 / (1 + lambda(wo) + lambda(wi)); }
    // Any model; h is the microfacet normal (h.z > 0). Sides are the caller's to check.
    float G(Vec3 wo, Vec3 wi, Vec3 h, MaskingModel model) const {
        switch (model) {
            case MaskingModel::SmithSeparable: return G1(wo) * G1(wi);
            case MaskingModel::VCavity: {
                const float ho = std::abs(dot(wo, h)), hi = std::abs(dot(wi, h));
                if (ho <= 0 || hi <= 0) return 0;
                return std::min(
                    {1.0f, 2 * h.z * std::abs(wo.z) / ho, 2 * h.z * std::abs(wi.z) / hi});
            }
            case MaskingModel::SmithCorrelated: break;
        }
        return G(wo, wi);
    }

    float pdf_visible(Vec3 wo, Vec3 h) const {
        return visit([&](const auto& d) { return d.pdf_visible(wo, h); });
    }
    Vec3 sample_visible(Vec3 wo, Vec2 u) const {
        return visit([&](const auto& d) { return d.sample_visible(wo, u); });
    }
    float pdf_D(Vec3 h) const { return D(h) * std::max(0.0f, h.z); }
    Vec3 sample_D(Vec2 u) const { return visit([&](const auto& d) { return d.sample_D(u); }); }

    // The sampling that suits the masking model: visible normals go with Smith masking,
    // whose G1 normalizes them; the V-cavity term does not, so it samples D. wo.z > 0;
    // the density is per unit solid angle of h.
    Vec3 sample(Vec3 wo, Vec2 u, MaskingModel model) const {
        return model == MaskingModel::VCavity ? sample_D(u) : sample_visible(wo, u);
    }
    float pdf(Vec3 wo, Vec3 h, MaskingModel model) const {
        return model == MaskingModel::VCavity ? pdf_D(h) : pdf_visible(wo, h);
    }

private:
    // Calls f with the concrete distribution; both are just two alphas, so this is free.
    template <typename F>
    auto visit(F&& f) const -> decltype(f(GgxDistribution(1))) {
        if (m_type == MicrofacetType::Beckmann) return f(BeckmannDistribution(m_alpha, m_alpha_y));
        return f(GgxDistribution(m_alpha, m_alpha_y));
    }

    MicrofacetType m_type;
    float m_alpha;  // alpha_x
    float m_alpha_y;
};

}  // namespace penumbra
