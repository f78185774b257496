#include "core/lights/environment_light.h"

#include <cmath>
#include <limits>

#include "core/math/atan2.h"
#include "core/sampling/warp.h"
#include "core/math/portable_math.h"

namespace penumbra {

EnvironmentLight::EnvironmentLight(Spectrum radiance, float scene_radius)
    : m_constant(radiance), m_radius(scene_radius) {}

EnvironmentLight::EnvironmentLight(Image image, float intensity, float rotation_degrees,
                                   float scene_radius, EnvironmentSampling sampling)
    : m_image(std::move(image)), m_scale(intensity), m_radius(scene_radius) {
    const float r = rotation_degrees * kPi / 180.0f;
    m_cos_rot = portable_cos(r);
    m_sin_rot = portable_sin(r);
    const int w = m_image.width, h = m_image.height;
    std::vector<float> func(size_t(w) * h);
    m_radiance.resize(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) m_radiance[size_t(y) * w + x] = m_image.rgba(x, y).xyz() * m_scale;
    std::vector<float> sin_theta(size_t(h), 0.0f);
    double weighted = 0, weights = 0;  // for the mean luminance over the sphere
    for (int y = 0; y < h; ++y) {
        sin_theta[y] = portable_sin(kPi * (y + 0.5f) / h);
        for (int x = 0; x < w; ++x) {
            func[size_t(y) * w + x] = luminance(m_image.rgba(x, y).xyz()) * sin_theta[y];
            weighted += func[size_t(y) * w + x];
        }
        weights += double(sin_theta[y]) * w;
    }
    m_dist = Distribution2D(func, w, h);
    m_luminance_integral = m_dist.integral();
    if (sampling != EnvironmentSampling::MisCompensated || !(weights > 0)) return;
    const float mean = float(weighted / weights);
    bool any = false;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float& f = func[size_t(y) * w + x];
            const float above = luminance(m_image.rgba(x, y).xyz()) - mean;
            f = above > 0 ? above * sin_theta[y] : 0.0f;
            any = any || f > 0;
        }
    if (!any) return;  // a constant map: nothing above its mean
    m_dist = Distribution2D(func, w, h);
    m_sampling = EnvironmentSampling::MisCompensated;
}

const char* environment_sampling_name(const EnvironmentLight* env) {
    if (!env) return "none";
    return env->sampling() == EnvironmentSampling::MisCompensated ? "compensated" : "full";
}

Vec2 EnvironmentLight::direction_to_uv(Vec3 w) const {
    // Undo the rotation about +Y.
    const float x = m_cos_rot * w.x - m_sin_rot * w.z;
    const float z = m_sin_rot * w.x + m_cos_rot * w.z;
    // atan2 keeps theta accurate near the poles, where acos(y) loses digits.
    const float theta = atan2_fast(std::sqrt(x * x + z * z), w.y);
    const float phi = atan2_fast(-z, -x);
    float u = phi * kInv2Pi + 0.5f;
    if (u >= 1) u -= 1;
    return {u, theta * kInvPi};
}

Vec3 EnvironmentLight::uv_to_direction(Vec2 uv) const {
    const float theta = uv.y * kPi, phi = (uv.x - 0.5f) * 2 * kPi;
    const float s = portable_sin(theta);
    const float x = -s * portable_cos(phi), z = -s * portable_sin(phi), y = portable_cos(theta);
    return {m_cos_rot * x + m_sin_rot * z, y, -m_sin_rot * x + m_cos_rot * z};
}

Spectrum EnvironmentLight::texel_radiance(Vec2 uv) const {
    const int x = std::min(static_cast<int>(uv.x * m_image.width), m_image.width - 1);
    const int y = std::min(static_cast<int>(uv.y * m_image.height), m_image.height - 1);
    // Nearest texel: the same piecewise-constant function the sampler's pdf follows.
    return m_radiance[size_t(y) * m_image.width + x];
}

float EnvironmentLight::uv_pdf(Vec2 uv) const {
    // Jacobian of (u, v) -> direction: 2 pi^2 sin(theta).
    const float sin_theta = portable_sin(uv.y * kPi);
    if (!(sin_theta > 0)) return 0;
    return m_dist.pdf(uv) / (2 * kPi * kPi * sin_theta);
}

Spectrum EnvironmentLight::Le(Vec3 w) const {
    if (m_image.width == 0) return m_constant;
    return texel_radiance(direction_to_uv(w));
}

Spectrum EnvironmentLight::Le(Vec3 w, float* pdf) const {
    if (m_image.width == 0) {
        *pdf = is_black(m_constant) ? 0.0f : uniform_sphere_pdf();
        return m_constant;
    }
    const Vec2 uv = direction_to_uv(w);
    *pdf = uv_pdf(uv);
    return texel_radiance(uv);
}

std::optional<LightSample> EnvironmentLight::sample_Li(const ShadingPoint&, Vec2 u,
                                                       float) const {
    constexpr float inf = std::numeric_limits<float>::infinity();
    if (m_image.width == 0) {
        if (is_black(m_constant)) return std::nullopt;
        const Vec3 wi = square_to_uniform_sphere(u);
        return LightSample{wi, inf, m_constant, uniform_sphere_pdf(), false, {}};
    }
    float pdf_uv;
    const Vec2 uv = m_dist.sample(u, &pdf_uv);
    if (!(pdf_uv > 0)) return std::nullopt;
    const Vec3 wi = uv_to_direction(uv);
    // The density as pdf_Li reports it for wi, so that MIS sees one consistent value
    // even where float round-off moves wi across a texel edge; Le from the same (u, v)
    // (one atan2 pair, not two).
    const Vec2 uv_wi = direction_to_uv(wi);
    const float pdf = uv_pdf(uv_wi);
    if (!(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
    return LightSample{wi, inf, texel_radiance(uv_wi), pdf, false, {}};  // no point: at infinity
}

float EnvironmentLight::pdf_Li(const ShadingPoint&, Vec3 wi, float) const {
    if (m_image.width == 0) return is_black(m_constant) ? 0.0f : uniform_sphere_pdf();
    return uv_pdf(direction_to_uv(wi));
}

float EnvironmentLight::power() const {
    // Flux through a disk of the scene's radius: pi r^2 times the integral of L over
    // the sphere (mean radiance times 4 pi).
    float mean;
    if (m_image.width == 0) {
        mean = luminance(m_constant);
    } else {
        // The distribution's integral is the mean of luminance * sin(theta) over the
        // image; dividing by the mean of sin(theta) (2/pi) gives mean radiance.
        mean = m_scale * m_luminance_integral / (2 * kInvPi);
    }
    return kPi * m_radius * m_radius * 4 * kPi * mean;
}

}  // namespace penumbra
