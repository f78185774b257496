// Test helper: two surface points equal bit for bit (signed zeros and NaNs included),
// for code that must give make_surface_point's values exactly.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/surface_point.h"

namespace penumbra::test {

inline bool same_bits(const float* a, const float* b, size_t n) {
    return std::memcmp(a, b, n * sizeof(float)) == 0;
}

// Every field of a and b, named in the failure message with `where`.
inline void expect_same_surface_point(const SurfacePoint& a, const SurfacePoint& b,
                                      const std::string& where) {
    auto vec3 = [&](const char* name, Vec3 x, Vec3 y) {
        EXPECT_TRUE(same_bits(&x.x, &y.x, 1) && same_bits(&x.y, &y.y, 1) &&
                    same_bits(&x.z, &y.z, 1))
            << where << ": " << name << " (" << x.x << ", " << x.y << ", " << x.z << ") vs ("
            << y.x << ", " << y.y << ", " << y.z << ")";
    };
    vec3("p", a.p, b.p);
    vec3("p_smooth", a.p_smooth, b.p_smooth);
    vec3("p_error", a.p_error, b.p_error);
    vec3("ng", a.ng, b.ng);
    EXPECT_EQ(a.ng_is_front, b.ng_is_front) << where;
    vec3("ns", a.ns, b.ns);
    vec3("dpdu", a.dpdu, b.dpdu);
    const float ta[4] = {a.tangent.x, a.tangent.y, a.tangent.z, a.tangent.w};
    const float tb[4] = {b.tangent.x, b.tangent.y, b.tangent.z, b.tangent.w};
    EXPECT_TRUE(same_bits(ta, tb, 4)) << where << ": tangent";
    const float ua[4] = {a.uv0.x, a.uv0.y, a.uv1.x, a.uv1.y};
    const float ub[4] = {b.uv0.x, b.uv0.y, b.uv1.x, b.uv1.y};
    EXPECT_TRUE(same_bits(ua, ub, 4)) << where << ": uv";
    EXPECT_TRUE(same_bits(&a.cone_width, &b.cone_width, 1)) << where << ": cone_width";
    EXPECT_TRUE(same_bits(a.uv_width, b.uv_width, 2)) << where << ": uv_width";
    const float ca[4] = {a.color.x, a.color.y, a.color.z, a.color.w};
    const float cb[4] = {b.color.x, b.color.y, b.color.z, b.color.w};
    EXPECT_TRUE(same_bits(ca, cb, 4)) << where << ": color";
    EXPECT_TRUE(same_bits(&a.t, &b.t, 1)) << where << ": t";
    EXPECT_EQ(a.instance, b.instance) << where;
    EXPECT_EQ(a.mesh, b.mesh) << where;
    EXPECT_EQ(a.prim, b.prim) << where;
    EXPECT_EQ(a.material, b.material) << where;
}

}  // namespace penumbra::test
