#include "core/lights/light_bounds.h"

#include <algorithm>
#include <cmath>

#include "core/math/portable_math.h"

namespace penumbra {

namespace {

float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
float safe_acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of a and b in
// [0, pi] (pbrt-v4's cosSubClamped / sinSubClamped).
float cos_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a > cos_b) return 1;
    return cos_a * cos_b + sin_a * sin_b;
}
float sin_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a > cos_b) return 0;
    return sin_a * cos_b - cos_a * sin_b;
}

// Rodrigues' rotation of v about unit axis k by angle theta.
Vec3 rotate(Vec3 v, Vec3 k, float theta) {
    const float c = portable_cos(theta), s = portable_sin(theta);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

// The smallest cone (axis, cos) holding both (pbrt-v4's Union of DirectionCones).
void merge_cones(Vec3 wa, float cos_a, Vec3 wb, float cos_b, Vec3* w, float* cos_o) {
    const float theta_a = safe_acos(cos_a), theta_b = safe_acos(cos_b);
    const float theta_d = safe_acos(dot(wa, wb));
    if (std::min(theta_d + theta_b, kPi) <= theta_a) {
        *w = wa, *cos_o = cos_a;
        return;
    }
    if (std::min(theta_d + theta_a, kPi) <= theta_b) {
        *w = wb, *cos_o = cos_b;
        return;
    }
    const float theta_o = (theta_a + theta_d + theta_b) / 2;
    const Vec3 axis = cross(wa, wb);
    if (theta_o >= kPi || !(length_squared(axis) > 0)) {
        *w = wa, *cos_o = -1;  // the whole sphere
        return;
    }
    *w = normalize(rotate(wa, normalize(axis), theta_o - theta_a));
    *cos_o = portable_cos(theta_o);
}

}  // namespace

float LightBounds::importance(Vec3 p, Vec3 n) const {
    const Vec3 pc = centroid();
    const Vec3 d = p - pc;
    const float half_diag2 = 0.25f * length_squared(hi - lo);
    // Inside the box the distance says nothing; its size bounds how close the lights are.
    const float d2 = std::max({length_squared(d), half_diag2, 1e-20f});
    const float len = std::sqrt(length_squared(d));
    const Vec3 dir = len > 0 ? d / len : w;  // from the lights to p
    float cos_w = dot(dir, w);
    if (two_sided) cos_w = std::abs(cos_w);
    const float sin_w = safe_sqrt(1 - cos_w * cos_w);

    // theta_b: the cone of directions from p that holds the box (its bounding sphere).
    float cos_b = -1;
    const bool inside =
        p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
    if (!inside && length_squared(d) > half_diag2)
        cos_b = safe_sqrt(1 - half_diag2 / length_squared(d));
    const float sin_b = safe_sqrt(1 - cos_b * cos_b);

    // theta' = max(0, theta_w - theta_o - theta_b): the smallest angle between p and the
    // normal of any emitter inside.
    const float sin_o = safe_sqrt(1 - cos_theta_o * cos_theta_o);
    const float cos_x = cos_sub_clamped(sin_w, cos_w, sin_o, cos_theta_o);
    const float sin_x = sin_sub_clamped(sin_w, cos_w, sin_o, cos_theta_o);
    const float cos_p = cos_sub_clamped(sin_x, cos_x, sin_b, cos_b);
    // Strictly outside the emission spread nothing arrives; at theta' = theta_e exactly a
    // Lambertian side's cosine is 0, and a spot's cone (theta_e = 0) still reaches p.
    if (cos_p < cos_theta_e) return 0;
    float importance = phi * std::max(0.0f, cos_p) / d2;

    // The receiver's cosine, bounded the same way (|cos|: transmission sees both sides).
    if (n.x != 0 || n.y != 0 || n.z != 0) {
        const float cos_i = len > 0 ? absdot(dir, n) : 1;
        const float sin_i = safe_sqrt(1 - cos_i * cos_i);
        importance *= std::max(0.0f, cos_sub_clamped(sin_i, cos_i, sin_b, cos_b));
    }
    return importance;
}

LightBounds merge(const LightBounds& a, const LightBounds& b) {
    if (!(a.phi > 0)) return b;
    if (!(b.phi > 0)) return a;
    LightBounds m;
    m.lo = min(a.lo, b.lo);
    m.hi = max(a.hi, b.hi);
    m.phi = a.phi + b.phi;
    merge_cones(a.w, a.cos_theta_o, b.w, b.cos_theta_o, &m.w, &m.cos_theta_o);
    m.cos_theta_e = std::min(a.cos_theta_e, b.cos_theta_e);
    m.two_sided = a.two_sided || b.two_sided;
    return m;
}

}  // namespace penumbra
