#include "core/sampling/warp.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/math/portable_math.h"

namespace penumbra {

Vec2 cos_sin_quarter_pi_for_test(float a) { return warp_detail::cos_sin_quarter_pi(a); }

Vec2 square_to_concentric_disk(Vec2 u) {
    float radius;
    return warp_detail::concentric_disk(u, &radius);
}

float polygon_area(int blades) { return 0.5f * blades * portable_sin(2 * kPi / blades); }

Vec2 square_to_polygon(Vec2 u, int blades, float rotation) {
    // All wedges have equal area, so choose one uniformly and reuse the leftover of u.x.
    const float scaled = u.x * blades;
    const int k = std::min(static_cast<int>(scaled), blades - 1);
    const float ux = scaled - k;
    const float a0 = rotation + 2 * kPi * k / blades;
    const float a1 = rotation + 2 * kPi * (k + 1) / blades;
    // Uniform point in the triangle (center, v0, v1).
    const Vec2 b = square_to_triangle({ux, u.y});
    const Vec2 v0{portable_cos(a0), portable_sin(a0)}, v1{portable_cos(a1), portable_sin(a1)};
    return v0 * b.x + v1 * b.y;
}

Vec3 square_to_uniform_sphere(Vec2 u) {
    const float z = 1 - 2 * u.x;
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    const float phi = 2 * kPi * u.y;
    return {r * portable_cos(phi), r * portable_sin(phi), z};
}

Vec3 square_to_uniform_hemisphere(Vec2 u) {
    const float z = u.x;
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    const float phi = 2 * kPi * u.y;
    return {r * portable_cos(phi), r * portable_sin(phi), z};
}

Vec3 square_to_uniform_cone(Vec2 u, float cos_max) {
    const float cos_theta = (1 - u.x) + u.x * cos_max;
    const float sin_theta = std::sqrt(std::max(0.0f, 1 - cos_theta * cos_theta));
    const float phi = 2 * kPi * u.y;
    return {sin_theta * portable_cos(phi), sin_theta * portable_sin(phi), cos_theta};
}

float uniform_cone_pdf(float cos_max) { return 1.0f / (2 * kPi * (1 - cos_max)); }

Vec2 square_to_triangle(Vec2 u) {
    // Heitz's two branches (halve the smaller coordinate, subtract it from the larger)
    // without a branch, which mispredicts half the time: the other coordinate minus half
    // of itself is its half exactly (Sterbenz), so the results are the branches' own.
    const float h = std::min(u.x, u.y) * 0.5f;
    return {u.x - h, u.y - h};
}

}  // namespace penumbra
