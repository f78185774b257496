// The glTF inputs of the specular lobe at a hit (materials/specular_inputs.h): the
// anisotropy direction from TANGENT or dp/du, rotation and texture, its strength, and the
// thin film's factor and thickness from factors and textures.
#include "materials/specular_inputs.h"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

// A one-texel texture holding rgba, appended to scene; returns a reference to it.
TextureRef add_texel(Scene& scene, Vec4 rgba) {
    Image img(1, 1, 4);
    for (int c = 0; c < 4; ++c) img.pixels[c] = rgba[c];
    scene.images.push_back(TextureImage(img));
    Texture tex;
    tex.image = uint32_t(scene.images.size() - 1);
    scene.textures.push_back(tex);
    TextureRef ref;
    ref.texture = int(scene.textures.size() - 1);
    return ref;
}

SurfacePoint flat_point(Vec4 tangent, Vec3 dpdu = Vec3(0, 0, 0)) {
    SurfacePoint sp;
    sp.ng = sp.ns = Vec3(0, 0, 1);
    sp.tangent = tangent;
    sp.dpdu = dpdu;
    return sp;
}

void expect_direction(Vec3 a, Vec3 b, const char* what) {
    // The BRDF is symmetric under x -> -x: only the line matters.
    EXPECT_NEAR(std::abs(dot(a, b)), 1.0f, 1e-5f) << what;
}

TEST(SpecularInputs, AnisotropyFollowsTangentAndRotation) {
    Scene scene;
    MaterialDesc m;
    m.anisotropy_strength = 0.6f;
    // TANGENT along +x with bitangent sign +1: b = cross(n, t) = +y; rotation 30 degrees
    // counter-clockwise from t towards b.
    m.anisotropy_rotation = kPi / 6;
    Frame f = Frame::from_normal(Vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(align_anisotropy_frame(scene, m, flat_point({1, 0, 0, 1}), f), 0.6f);
    expect_direction(f.s, Vec3(std::cos(kPi / 6), std::sin(kPi / 6), 0), "rotation");
    EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-6f);
    EXPECT_NEAR(length(cross(f.s, f.t) - f.n), 0.0f, 1e-5f);
    // Bitangent sign -1 mirrors the tangent space: b = -y.
    f = Frame::from_normal(Vec3(0, 0, 1));
    align_anisotropy_frame(scene, m, flat_point({1, 0, 0, -1}), f);
    expect_direction(f.s, Vec3(std::cos(kPi / 6), -std::sin(kPi / 6), 0), "bitangent sign");
    // Seen from the back (the frame flipped to the viewer), the direction stays on the
    // surface where it was.
    f = Frame::from_normal(Vec3(0, 0, -1));
    align_anisotropy_frame(scene, m, flat_point({1, 0, 0, 1}), f);
    expect_direction(f.s, Vec3(std::cos(kPi / 6), std::sin(kPi / 6), 0), "back side");
    // Without TANGENT, dp/du (made orthogonal to the normal).
    f = Frame::from_normal(Vec3(0, 0, 1));
    m.anisotropy_rotation = 0;
    align_anisotropy_frame(scene, m, flat_point({0, 0, 0, 0}, {0.3f, 1, 0.5f}), f);
    expect_direction(f.s, normalize(Vec3(0.3f, 1, 0)), "dp/du");
    // No tangent at all: isotropic, the frame untouched.
    const Frame before = Frame::from_normal(Vec3(0, 0, 1));
    f = before;
    EXPECT_EQ(align_anisotropy_frame(scene, m, flat_point({0, 0, 0, 0}), f), 0.0f);
    EXPECT_EQ(f.s, before.s);
}

TEST(SpecularInputs, AnisotropyTexture) {
    // RG (0.5, 1) is the direction (0, 1) in [-1, 1]: +90 degrees, then rotated by
    // another 45: 135 degrees from the tangent; B scales the strength.
    Scene scene;
    MaterialDesc m;
    m.anisotropy_strength = 0.8f;
    m.anisotropy_rotation = kPi / 4;
    m.anisotropy_texture = add_texel(scene, {0.5f, 1, 0.5f, 1});
    Frame f = Frame::from_normal(Vec3(0, 0, 1));
    EXPECT_NEAR(align_anisotropy_frame(scene, m, flat_point({1, 0, 0, 1}), f), 0.4f, 1e-6f);
    expect_direction(f.s, Vec3(std::cos(3 * kPi / 4), std::sin(3 * kPi / 4), 0), "texture");
    // B = 0: no anisotropy.
    Scene none;
    m.anisotropy_texture = add_texel(none, {1, 0.5f, 0, 1});
    f = Frame::from_normal(Vec3(0, 0, 1));
    EXPECT_EQ(align_anisotropy_frame(none, m, flat_point({1, 0, 0, 1}), f), 0.0f);
}

TEST(SpecularInputs, IridescenceFactorAndThickness) {
    Scene scene;
    MaterialDesc m;
    MetalRoughParams p;
    set_iridescence(scene, m, flat_point({}), p);  // factor 0: no film
    EXPECT_EQ(p.iridescence, 0.0f);
    m.iridescence = 0.9f;
    m.iridescence_ior = 1.7f;
    set_iridescence(scene, m, flat_point({}), p);  // no textures: the maximum thickness
    EXPECT_EQ(p.iridescence, 0.9f);
    EXPECT_EQ(p.film.ior, 1.7f);
    EXPECT_EQ(p.film.thickness, 400.0f);
    m.iridescence_texture = add_texel(scene, {0.5f, 0, 0, 1});
    m.iridescence_thickness_texture = add_texel(scene, {0, 0.25f, 0, 1});
    set_iridescence(scene, m, flat_point({}), p);
    EXPECT_NEAR(p.iridescence, 0.45f, 1e-6f);
    EXPECT_NEAR(p.film.thickness, 100 + 0.25f * 300, 1e-3f);
}

}  // namespace
}  // namespace penumbra
