// shade() for the glTF extensions that add lobes or change the model: clearcoat, sheen
// and diffuse transmission become a GltfBsdf only when active (factor 0 keeps the plain
// model), their textures scale their factors, the coat follows its own normal map and
// not the base's, KHR_materials_unlit emits its base colour and reflects nothing,
// pbrSpecularGlossiness and the KHR_materials_specular textures set f0.
#include <gtest/gtest.h>

#include "materials/lobes/fresnel.h"
#include "materials/material.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

SurfacePoint flat_point(int material) {
    SurfacePoint sp;
    sp.ng = sp.ns = Vec3(0, 0, 1);
    sp.dpdu = Vec3(1, 0, 0);
    sp.uv0 = sp.uv1 = {0.5f, 0.5f};
    sp.material = material;
    return sp;
}

// A 1 x 1 texture of one RGBA value; returns its index for a TextureRef.
int add_texture(Scene& scene, Vec4 v) {
    Image img(1, 1, 4);
    for (int c = 0; c < 4; ++c) img.at(0, 0)[c] = v[c];
    scene.images.push_back(TextureImage(img));
    Texture tex;
    tex.image = uint32_t(scene.images.size() - 1);
    tex.nearest = true;
    scene.textures.push_back(tex);
    return int(scene.textures.size() - 1);
}

MaterialDesc dielectric() {
    MaterialDesc m;
    m.base_color = {0.7f, 0.5f, 0.3f, 1};
    m.metallic = 0;
    m.roughness = 0.4f;
    return m;
}

MetalRoughParams params_of(const MaterialDesc& m) {
    MetalRoughParams p;
    p.base_color = m.base_color.xyz();
    p.metallic = m.metallic;
    p.alpha = m.roughness * m.roughness;
    p.dielectric_f0 = Spectrum(f0_from_ior(m.ior));  // as shade() computes it
    return p;
}

// Both BSDFs give the same value and density, bit for bit, at random pairs.
void expect_same(const Bsdf& a, const Bsdf& b, bool sphere = false) {
    Rng rng(11);
    for (int i = 0; i < 300; ++i) {
        const Vec3 wo = test::random_direction(rng, 0.01f);
        const Vec3 wi = test::random_direction(rng, 0.01f, sphere && i % 2);
        ASSERT_EQ(a.eval(wo, wi, Transport::Radiance), b.eval(wo, wi, Transport::Radiance));
        ASSERT_EQ(a.pdf(wo, wi, Transport::Radiance), b.pdf(wo, wi, Transport::Radiance));
    }
}

const Vec3 kUp(0, 0, 1);

TEST(ShadeLayers, InactiveLayersKeepThePlainModel) {
    // Factors 1 with textures at 0, and factors 0 with textures at 1.
    for (float factor : {1.0f, 0.0f}) {
        Scene scene;
        const Vec4 texel(1 - factor, 1 - factor, 1 - factor, 1 - factor);
        MaterialDesc m = dielectric();
        m.clearcoat = factor;
        m.clearcoat_texture.texture = add_texture(scene, texel);
        m.sheen_color = Spectrum(factor);
        m.sheen_color_texture.texture = add_texture(scene, texel);
        m.diffuse_transmission = factor;
        m.diffuse_transmission_texture.texture = add_texture(scene, texel);
        scene.materials.push_back(m);
        const ShadingData sd = shade(scene, flat_point(0), kUp);
        ASSERT_NE(dynamic_cast<const MetalRoughBsdf*>(sd.bsdf.get()), nullptr) << factor;
        expect_same(*sd.bsdf.get(), MetalRoughBsdf(params_of(m)));
    }
}

TEST(ShadeLayers, TexturesScaleTheLayers) {
    Scene scene;
    MaterialDesc m = dielectric();
    m.clearcoat = 0.8f;
    m.clearcoat_texture.texture = add_texture(scene, {0.5f, 0, 0, 1});  // R
    m.clearcoat_roughness = 0.6f;
    m.clearcoat_roughness_texture.texture = add_texture(scene, {0, 0.5f, 0, 1});  // G
    m.sheen_color = {1, 0.5f, 0.5f};
    m.sheen_color_texture.texture = add_texture(scene, {0.5f, 1, 0.2f, 1});  // RGB
    m.sheen_roughness = 0.8f;
    m.sheen_roughness_texture.texture = add_texture(scene, {0, 0, 0, 0.5f});  // A
    m.diffuse_transmission = 0.6f;
    m.diffuse_transmission_texture.texture = add_texture(scene, {0, 0, 0, 0.5f});  // A
    m.diffuse_transmission_color = {1, 0.5f, 1};
    m.diffuse_transmission_color_texture.texture = add_texture(scene, {0.2f, 1, 0.5f, 1});
    scene.materials.push_back(m);
    const ShadingData sd = shade(scene, flat_point(0), kUp);
    ASSERT_NE(dynamic_cast<const GltfBsdf*>(sd.bsdf.get()), nullptr);

    DiffuseTransmissionParams dt;
    dt.factor = 0.3f;
    dt.color = {0.2f, 0.5f, 0.5f};
    DielectricParams d;
    d.eta = 1.5f;
    d.alpha = 0.4f * 0.4f;
    d.transmittance = m.base_color.xyz();
    const GltfBsdf expected(GltfDiffuseTransmissionBsdf(params_of(m), dt, 0, d),
                            SheenLobe({0.5f, 0.5f, 0.1f}, 0.4f),
                            ClearcoatLobe(0.4f, 0.3f * 0.3f, kUp, MicrofacetType::Ggx));
    expect_same(*sd.bsdf.get(), expected, true);
}

// The world direction of the mirror coat's reflection at the point.
std::optional<Vec3> coat_mirror(const ShadingData& sd, Vec3 wo_world) {
    const Vec3 wo = sd.frame.to_local(wo_world);
    for (int i = 0; i < 100; ++i) {
        const auto s =
            sd.bsdf.get()->sample(wo, (i + 0.5f) / 100, {0.5f, 0.5f}, Transport::Radiance);
        if (s && s->is_specular()) return sd.frame.to_world(s->wi);
    }
    return std::nullopt;
}

TEST(ShadeLayers, CoatFollowsItsOwnNormalMapNotTheBase) {
    Scene scene;
    MaterialDesc m;
    m.metallic = 1;
    m.roughness = 0.5f;
    // A tangent-space normal leaning towards +u: (0.4, 0, 0.92) encoded as (x + 1) / 2.
    const Vec3 leaning = normalize(Vec3(0.4f, 0, 0.92f));
    m.normal_texture.texture =
        add_texture(scene, {(leaning.x + 1) / 2, (leaning.y + 1) / 2, (leaning.z + 1) / 2, 1});
    m.clearcoat = 1;
    m.clearcoat_roughness = 0;
    scene.materials.push_back(m);
    const Vec3 wo = normalize(Vec3(-0.3f, 0.2f, 0.9f));
    // Without its own map the coat reflects about the interpolated normal.
    const ShadingData plain = shade(scene, flat_point(0), wo);
    EXPECT_GT(plain.frame.n.x, 0.1f);  // the base is normal-mapped
    const std::optional<Vec3> a = coat_mirror(plain, wo);
    ASSERT_TRUE(a);
    const Vec3 ea = reflect(wo, kUp);
    EXPECT_NEAR(length(*a - ea), 0, 1e-5f);
    // With the map as clearcoatNormalTexture it reflects about the mapped normal.
    scene.materials[0].clearcoat_normal_texture = m.normal_texture;
    const ShadingData mapped = shade(scene, flat_point(0), wo);
    const std::optional<Vec3> b = coat_mirror(mapped, wo);
    ASSERT_TRUE(b);
    const Vec3 eb = reflect(wo, mapped.frame.n);
    EXPECT_NEAR(length(*b - eb), 0, 1e-5f);
    EXPECT_GT(length(*b - ea), 0.1f);
}

TEST(ShadeLayers, UnlitEmitsItsBaseColourAndReflectsNothing) {
    Scene scene;
    MaterialDesc m;
    m.unlit = true;
    m.base_color = {0.5f, 0.8f, 1, 1};
    m.base_color_texture.texture = add_texture(scene, {1, 0.5f, 0.5f, 1});
    m.emissive = {1, 1, 1};  // ignored: unlit shows its base colour only
    scene.materials.push_back(m);
    SurfacePoint sp = flat_point(0);
    sp.color = {0.5f, 1, 1, 1};
    const ShadingData sd = shade(scene, sp, kUp);
    EXPECT_EQ(sd.emission, Spectrum(0.25f, 0.4f, 0.5f));
    Rng rng(12);
    for (int i = 0; i < 100; ++i) {
        const Vec3 wo = test::random_direction(rng), wi = test::random_direction(rng);
        EXPECT_EQ(sd.bsdf.get()->eval(wo, wi, Transport::Radiance), Spectrum(0));
        const auto s = sd.bsdf.get()->sample(
            wo, rng.next_float(), {rng.next_float(), rng.next_float()}, Transport::Radiance);
        if (s) {
            EXPECT_TRUE(is_black(s->weight()));
        }
    }
}

TEST(ShadeLayers, SpecularGlossinessIsADielectricWithF0) {
    Scene scene;
    MaterialDesc m;
    m.specular_glossiness = true;
    m.base_color = {0.6f, 0.3f, 0.2f, 1};  // diffuse
    m.specular_color = {0.9f, 0.6f, 0.3f};
    m.roughness = 0.2f;  // glossiness 0.8
    m.metallic = 1;      // the loader sets 0; the model must not care
    m.specular_glossiness_texture.texture = add_texture(scene, {0.5f, 1, 0.5f, 0.5f});
    scene.materials.push_back(m);
    const ShadingData sd = shade(scene, flat_point(0), kUp);
    MetalRoughParams p;
    p.base_color = {0.6f, 0.3f, 0.2f};
    p.metallic = 0;
    const float roughness = 1 - (1 - 0.2f) * 0.5f;  // 1 - glossiness x texture A
    p.alpha = roughness * roughness;
    p.dielectric_f0 = Spectrum(0.9f, 0.6f, 0.3f) * Spectrum(0.5f, 1, 0.5f);
    p.dielectric_f90 = 1;
    expect_same(*sd.bsdf.get(), MetalRoughBsdf(p));
}

TEST(ShadeLayers, SpecularTexturesScaleFactorAndColour) {
    Scene scene;
    MaterialDesc m = dielectric();
    m.specular = 0.8f;
    m.specular_texture.texture = add_texture(scene, {0, 0, 0, 0.5f});  // A
    m.specular_color = {1, 1, 0.5f};
    m.specular_color_texture.texture = add_texture(scene, {1, 0.5f, 0.5f, 0});  // RGB
    scene.materials.push_back(m);
    const ShadingData sd = shade(scene, flat_point(0), kUp);
    MetalRoughParams p = params_of(m);
    p.dielectric_f0 = Spectrum(1, 0.5f, 0.25f) * f0_from_ior(1.5f) * 0.4f;
    p.dielectric_f90 = 0.4f;
    expect_same(*sd.bsdf.get(), MetalRoughBsdf(p));
}

}  // namespace
}  // namespace penumbra
