#include "io/color/color_primaries.h"

#include <array>

namespace penumbra {

namespace {

using D3 = std::array<double, 3>;

D3 apply(const Mat3& a, const D3& v) {
    D3 r{};
    for (int i = 0; i < 3; ++i) r[i] = a.m[i][0] * v[0] + a.m[i][1] * v[1] + a.m[i][2] * v[2];
    return r;
}

// XYZ of chromaticity xy at luminance Y = 1.
D3 xyz_of(const float xy[2]) {
    const double x = xy[0], y = xy[1];
    return {x / y, 1.0, (1 - x - y) / y};
}

const Chromaticities kRec709{{0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, {0.3127f, 0.3290f}};
const Chromaticities kAp1{
    {0.713f, 0.293f}, {0.165f, 0.830f}, {0.128f, 0.044f}, {0.32168f, 0.33767f}};
const Chromaticities kAp0{
    {0.7347f, 0.2653f}, {0.0f, 1.0f}, {0.0001f, -0.0770f}, {0.32168f, 0.33767f}};
const Chromaticities kRec2020{
    {0.708f, 0.292f}, {0.170f, 0.797f}, {0.131f, 0.046f}, {0.3127f, 0.3290f}};
const Chromaticities kP3D65{
    {0.680f, 0.320f}, {0.265f, 0.690f}, {0.150f, 0.060f}, {0.3127f, 0.3290f}};

}  // namespace

const Chromaticities& rec709_chromaticities() { return kRec709; }
const Chromaticities& ap1_chromaticities() { return kAp1; }
const Chromaticities& ap0_chromaticities() { return kAp0; }

const std::vector<NamedPrimaries>& known_primaries() {
    static const std::vector<NamedPrimaries> list = {
        {"Rec.709", kRec709},   {"ACES AP1", kAp1}, {"ACES AP0", kAp0},
        {"Rec.2020", kRec2020}, {"P3-D65", kP3D65},
    };
    return list;
}

Mat3 rgb_to_xyz(const Chromaticities& c) {
    // SMPTE RP 177: scale the primaries' XYZ so that RGB (1,1,1) lands on the white.
    Mat3 prim;
    const D3 r = xyz_of(c.red), g = xyz_of(c.green), b = xyz_of(c.blue);
    for (int i = 0; i < 3; ++i) {
        prim.m[i][0] = r[i];
        prim.m[i][1] = g[i];
        prim.m[i][2] = b[i];
    }
    Mat3 inv;
    if (!prim.inverse(&inv)) return Mat3::identity();
    const D3 s = apply(inv, xyz_of(c.white));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) prim.m[i][j] *= s[j];
    return prim;
}

Mat3 bradford(const float from_white[2], const float to_white[2]) {
    Mat3 b;
    b.m = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
    Mat3 b_inv;
    b.inverse(&b_inv);
    const D3 src = apply(b, xyz_of(from_white)), dst = apply(b, xyz_of(to_white));
    Mat3 scale;
    for (int i = 0; i < 3; ++i) scale.m[i][i] = dst[i] / src[i];
    return b_inv * scale * b;
}

Mat3 rgb_to_xyz_d65(const Chromaticities& c) {
    return bradford(c.white, kRec709.white) * rgb_to_xyz(c);
}

std::optional<Chromaticities> chromaticities_from_xyz_d65(const Mat3& to_xyz_d65,
                                                          double tolerance) {
    for (const NamedPrimaries& k : known_primaries())
        if (rgb_to_xyz_d65(k.xy).max_difference(to_xyz_d65) <= tolerance) return k.xy;

    Mat3 unused;
    if (!to_xyz_d65.inverse(&unused)) return std::nullopt;
    auto xy = [](const D3& v, float out[2]) {
        const double sum = v[0] + v[1] + v[2];
        if (!(sum > 0)) return false;
        out[0] = float(v[0] / sum);
        out[1] = float(v[1] / sum);
        return true;
    };
    Chromaticities c{};
    float* outs[3] = {c.red, c.green, c.blue};
    for (int j = 0; j < 3; ++j)
        if (!xy({to_xyz_d65.m[0][j], to_xyz_d65.m[1][j], to_xyz_d65.m[2][j]}, outs[j]))
            return std::nullopt;
    if (!xy(apply(to_xyz_d65, {1, 1, 1}), c.white)) return std::nullopt;
    return c;
}

}  // namespace penumbra
