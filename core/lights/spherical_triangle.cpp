#include "core/lights/spherical_triangle.h"

#include <algorithm>
#include <cmath>

#include "core/math/portable_math.h"

namespace penumbra {

namespace {

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
constexpr double kPiD = 3.14159265358979323846;

// Arvo's construction loses the shape of slivers and small triangles to float rounding
// (angles near 0 and pi, sums of sines that cancel), so it runs in double.
struct D3 {
    double x, y, z;
};
D3 d3(Vec3 v) { return {v.x, v.y, v.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator-(D3 a) { return {-a.x, -a.y, -a.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(D3 a) { return std::sqrt(dot(a, a)); }
D3 normalize(D3 a) { return a * (1 / length(a)); }

// Angle between unit vectors, accurate near 0 and pi (where acos of the dot product
// loses half its digits): 2 asin(|a - b| / 2).
double angle_between(D3 a, D3 b) {
    if (dot(a, b) < 0) return kPiD - 2 * std::asin(std::min(1.0, length(a + b) / 2));
    return 2 * std::asin(std::min(1.0, length(b - a) / 2));
}

// v without its component along unit w.
D3 gram_schmidt(D3 v, D3 w) { return v - w * dot(v, w); }

// The unit directions from p to the vertices, the unit normals of the great circles
// through each pair, and the angles at the vertices.
struct SphericalTriangle {
    D3 a, b, c;
    D3 n_ab, n_bc, n_ca;
    double alpha, beta, gamma;
};

// False when degenerate (p on a vertex, two directions parallel).
bool make_spherical_triangle(const Vec3 v[3], Vec3 p, SphericalTriangle& t) {
    const D3 a = d3(v[0]) - d3(p), b = d3(v[1]) - d3(p), c = d3(v[2]) - d3(p);
    if (!(dot(a, a) > 0) || !(dot(b, b) > 0) || !(dot(c, c) > 0)) return false;
    t.a = normalize(a);
    t.b = normalize(b);
    t.c = normalize(c);
    const D3 n_ab = cross(t.a, t.b), n_bc = cross(t.b, t.c), n_ca = cross(t.c, t.a);
    if (!(dot(n_ab, n_ab) > 0) || !(dot(n_bc, n_bc) > 0) || !(dot(n_ca, n_ca) > 0)) return false;
    t.n_ab = normalize(n_ab);
    t.n_bc = normalize(n_bc);
    t.n_ca = normalize(n_ca);
    // The angle at a vertex is the dihedral angle between the planes of its two edges.
    t.alpha = angle_between(t.n_ab, -t.n_ca);
    t.beta = angle_between(t.n_bc, -t.n_ab);
    t.gamma = angle_between(t.n_ca, -t.n_bc);
    return true;
}

// The density proportional to (1 - x) a + x b on [0,1], sampled by inverting its CDF in
// the form that stays finite as a or b goes to 0 (pbrt-v4's SampleLinear).
float sample_linear(float u, float a, float b) {
    if (u == 0 && a == 0) return 0;
    const float x = u * (a + b) / (a + std::sqrt((1 - u) * a * a + u * b * b));
    return std::min(x, kOneMinusEpsilon);
}

}  // namespace

float spherical_triangle_area(Vec3 a, Vec3 b, Vec3 c) {
    const D3 da = d3(a), db = d3(b), dc = d3(c);
    const double triple = std::abs(dot(da, cross(db, dc)));
    return float(std::abs(2 * std::atan2(triple, 1 + dot(da, db) + dot(db, dc) + dot(dc, da))));
}

float triangle_solid_angle(const Vec3 v[3], Vec3 p) {
    const D3 a = d3(v[0]) - d3(p), b = d3(v[1]) - d3(p), c = d3(v[2]) - d3(p);
    if (!(dot(a, a) > 0) || !(dot(b, b) > 0) || !(dot(c, c) > 0)) return 0;
    const D3 na = normalize(a), nb = normalize(b), nc = normalize(c);
    const double triple = std::abs(dot(na, cross(nb, nc)));
    return float(std::abs(2 * std::atan2(triple, 1 + dot(na, nb) + dot(nb, nc) + dot(nc, na))));
}

std::optional<Vec3> sample_spherical_triangle(const Vec3 v[3], Vec3 p, Vec2 u) {
    SphericalTriangle t;
    if (!make_spherical_triangle(v, p, t)) return std::nullopt;
    // Arvo 1995, section 3: choose the area A' of the sub-triangle (a, b, c') uniformly
    // in [0, A], which fixes the angle at c' ...
    const double A_pi = t.alpha + t.beta + t.gamma;  // area + pi
    const double Ap_pi = kPiD + u.x * (A_pi - kPiD);
    const double cos_alpha = portable_cos(t.alpha), sin_alpha = portable_sin(t.alpha);
    const double sin_phi = portable_sin(Ap_pi) * cos_alpha - portable_cos(Ap_pi) * sin_alpha;
    const double cos_phi = portable_cos(Ap_pi) * cos_alpha + portable_sin(Ap_pi) * sin_alpha;
    const double k1 = cos_phi + cos_alpha;
    const double k2 = sin_phi - sin_alpha * dot(t.a, t.b);
    // ... then solve for the cosine of the arc a c' (Arvo's eq. 8).
    double cos_bp = (k2 + (k2 * cos_phi - k1 * sin_phi) * cos_alpha) /
                    ((k2 * sin_phi + k1 * cos_phi) * sin_alpha);
    if (!std::isfinite(cos_bp)) return std::nullopt;
    cos_bp = std::clamp(cos_bp, -1.0, 1.0);
    const double sin_bp = std::sqrt(std::max(0.0, 1 - cos_bp * cos_bp));
    const D3 cp = t.a * cos_bp + normalize(gram_schmidt(t.c, t.a)) * sin_bp;
    // A point on the arc from b to c', uniform in the cosine to b (section 3.2).
    const double cos_theta = 1 - u.y * (1 - dot(cp, t.b));
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const D3 w = t.b * cos_theta + normalize(gram_schmidt(cp, t.b)) * sin_theta;
    // Where the ray (p, w) meets the triangle's plane, as barycentrics (Moller-Trumbore).
    const D3 e1 = d3(v[1]) - d3(v[0]), e2 = d3(v[2]) - d3(v[0]);
    const D3 s1 = cross(w, e2);
    const double divisor = dot(s1, e1);
    if (divisor == 0 || !std::isfinite(divisor)) return std::nullopt;
    const D3 s = d3(p) - d3(v[0]);
    double b1 = dot(s, s1) / divisor;
    double b2 = dot(w, cross(s, e1)) / divisor;
    // Rounding can put w a hair outside an edge.
    b1 = std::clamp(b1, 0.0, 1.0);
    b2 = std::clamp(b2, 0.0, 1.0);
    if (b1 + b2 > 1) {
        const double sum = b1 + b2;
        b1 /= sum;
        b2 /= sum;
    }
    if (!std::isfinite(b1) || !std::isfinite(b2)) return std::nullopt;
    return Vec3(float(1 - b1 - b2), float(b1), float(b2));
}

Vec2 invert_spherical_triangle_sample(const Vec3 v[3], Vec3 p, Vec3 w_in) {
    SphericalTriangle t;
    if (!make_spherical_triangle(v, p, t)) return {0.5f, 0.5f};
    const D3 w = normalize(d3(w_in));
    // c' is where the great circle through b and w meets the arc a c.
    D3 cp = cross(cross(t.b, w), cross(t.c, t.a));
    if (!(dot(cp, cp) > 0)) return {0.5f, 0.5f};
    cp = normalize(cp);
    if (dot(cp, t.a + t.c) < 0) cp = -cp;
    double u0 = 0;
    D3 n_cpb = cross(cp, t.b), n_acp = cross(t.a, cp);
    if (dot(n_cpb, n_cpb) > 0 && dot(n_acp, n_acp) > 1e-24) {  // else c' = a: u0 = 0
        n_cpb = normalize(n_cpb);
        n_acp = normalize(n_acp);
        // The sub-triangle (a, b, c') shares the angle at a with the whole one.
        const double Ap =
            t.alpha + angle_between(t.n_ab, n_cpb) + angle_between(n_acp, -n_cpb) - kPiD;
        const double A = t.alpha + t.beta + t.gamma - kPiD;
        u0 = Ap / A;
    }
    const double u1 = (1 - dot(w, t.b)) / (1 - dot(cp, t.b));
    return {float(std::clamp(u0, 0.0, 1.0)), float(std::clamp(u1, 0.0, 1.0))};
}

Vec2 sample_bilinear(Vec2 u, const float w[4]) {
    Vec2 p;
    p.y = sample_linear(u.y, w[0] + w[1], w[2] + w[3]);
    p.x = sample_linear(u.x, w[0] + (w[2] - w[0]) * p.y, w[1] + (w[3] - w[1]) * p.y);
    return p;
}

float bilinear_pdf(Vec2 p, const float w[4]) {
    if (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1) return 0;
    const float sum = w[0] + w[1] + w[2] + w[3];
    if (!(sum > 0)) return 1;
    return 4 *
           ((1 - p.x) * (1 - p.y) * w[0] + p.x * (1 - p.y) * w[1] + (1 - p.x) * p.y * w[2] +
            p.x * p.y * w[3]) /
           sum;
}

void receiver_cosine_weights(const Vec3 v[3], Vec3 p, Vec3 n, float w[4]) {
    float c[3];
    for (int k = 0; k < 3; ++k) c[k] = std::max(0.01f, absdot(n, normalize(v[k] - p)));
    // Corners (0,0) and (1,0) map to v[1], (0,1) to v[0], (1,1) to v[2].
    w[0] = c[1];
    w[1] = c[1];
    w[2] = c[0];
    w[3] = c[2];
}

}  // namespace penumbra
