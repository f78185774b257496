// shade(): glTF materials to BSDFs. Metallic 0 with specular 0 is exactly Lambertian,
// transmission refracts with ior from the front and 1/ior from the back (with a volume;
// without one it is a thin sheet that does not bend), the Beckmann
// option replaces GGX, and KHR_texture_transform moves every texture lookup.
#include "materials/material.h"

#include <gtest/gtest.h>

#include "core/scene/emission.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

// A hit at the origin on the z = 0 plane, geometric and shading normal +z.
SurfacePoint flat_point(int material, Vec2 uv = {0.25f, 0.25f}) {
    SurfacePoint sp;
    sp.ng = sp.ns = Vec3(0, 0, 1);
    sp.dpdu = Vec3(1, 0, 0);
    sp.uv0 = sp.uv1 = uv;
    sp.material = material;
    return sp;
}

Scene scene_with(const MaterialDesc& m) {
    Scene scene;
    scene.materials.push_back(m);
    return scene;
}

TEST(Shade, MetallicZeroSpecularZeroIsExactlyLambertian) {
    MaterialDesc m;
    m.base_color = {0.6f, 0.3f, 0.1f, 1};
    m.metallic = 0;
    m.specular = 0;
    m.roughness = 0.4f;
    const Scene scene = scene_with(m);
    const Vec3 wo_world = normalize(Vec3(0.3f, -0.2f, 0.8f));
    const ShadingData sd = shade(scene, flat_point(0), wo_world);
    const Bsdf& bsdf = *sd.bsdf.get();
    const LambertianBsdf lambert(Spectrum(0.6f, 0.3f, 0.1f));
    const Vec3 wo = sd.frame.to_local(wo_world);
    Rng rng(20);
    for (int i = 0; i < 500; ++i) {
        const Vec3 wi = test::random_direction(rng, 0.01f);
        EXPECT_EQ(bsdf.eval(wo, wi, Transport::Radiance),
                  lambert.eval(wo, wi, Transport::Radiance));
        EXPECT_EQ(bsdf.pdf(wo, wi, Transport::Radiance), lambert.pdf(wo, wi, Transport::Radiance));
        const float u_lobe = rng.next_float();
        const Vec2 u(rng.next_float(), rng.next_float());
        const auto a = bsdf.sample(wo, u_lobe, u, Transport::Radiance);
        const auto b = lambert.sample(wo, u_lobe, u, Transport::Radiance);
        ASSERT_EQ(bool(a), bool(b));
        if (a) {
            EXPECT_EQ(a->weight(), b->weight());
        }
    }
}

TEST(Shade, TransmissionRefractsByTheSideOfArrival) {
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = 0;
    m.roughness = 0;
    m.ior = 1.5f;
    m.transmission = 1;
    m.thickness = 1;  // KHR_materials_volume: a solid object, not a thin sheet
    const Scene scene = scene_with(m);
    for (bool front : {true, false}) {
        // From the back, wo is below the geometric normal; the frame flips to face it.
        const Vec3 wo_world = normalize(Vec3(0.5f, 0.1f, front ? 0.7f : -0.7f));
        const ShadingData sd = shade(scene, flat_point(0), wo_world);
        EXPECT_EQ(sd.front_face, front);
        const Vec3 wo = sd.frame.to_local(wo_world);
        ASSERT_GT(wo.z, 0.0f);
        const float eta = front ? 1.5f : 1 / 1.5f;
        const float F = fresnel_dielectric(wo.z, eta);
        const auto s =
            sd.bsdf.get()->sample(wo, F + 0.5f * (1 - F), {0.5f, 0.5f}, Transport::Radiance);
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->is_specular());
        EXPECT_EQ(s->eta, eta);
        const Vec3 wi_world = sd.frame.to_world(s->wi);
        // Crosses the surface, and Snell holds with the IOR of the side it enters.
        EXPECT_LT(wi_world.z * wo_world.z, 0.0f);
        const float sin_o = std::sqrt(1 - wo.z * wo.z), sin_i = std::sqrt(1 - s->wi.z * s->wi.z);
        EXPECT_NEAR(sin_o, eta * sin_i, 1e-5f);
        // The path integrator's side test accepts it: the flipped frame and flipped
        // geometric normal agree on which side wi is.
        EXPECT_EQ(s->wi.z > 0, dot(wi_world, sd.ng) > 0);
    }
}

TEST(Shade, ThinWalledTransmissionDoesNotBend) {
    // Without KHR_materials_volume: a sheet with IOR 1 on both sides (materials/
    // thin_dielectric.h), straight through from either side.
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = 0;
    m.roughness = 0;
    m.ior = 1.5f;
    m.transmission = 1;
    const Scene scene = scene_with(m);
    for (bool front : {true, false}) {
        const Vec3 wo_world = normalize(Vec3(0.5f, 0.1f, front ? 0.7f : -0.7f));
        const ShadingData sd = shade(scene, flat_point(0), wo_world);
        const Vec3 wo = sd.frame.to_local(wo_world);
        const auto s = sd.bsdf.get()->sample(wo, 0.999f, {0.5f, 0.5f}, Transport::Radiance);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->eta, 1.0f);
        EXPECT_NEAR(length(sd.frame.to_world(s->wi) + wo_world), 0.0f, 1e-6f);
    }
}

TEST(Shade, BeckmannOptionReplacesGgx) {
    MaterialDesc m;
    m.base_color = {0.9f, 0.8f, 0.7f, 1};
    m.metallic = 0.7f;
    m.roughness = 0.5f;
    const Scene scene = scene_with(m);
    const Vec3 wo_world = normalize(Vec3(0.2f, 0.3f, 0.9f));
    MaterialOptions beckmann;
    beckmann.gltf_distribution = MicrofacetType::Beckmann;
    const ShadingData g = shade(scene, flat_point(0), wo_world);
    const ShadingData b = shade(scene, flat_point(0), wo_world, beckmann);
    MetalRoughParams p;
    p.base_color = {0.9f, 0.8f, 0.7f};
    p.metallic = 0.7f;
    p.alpha = 0.25f;
    p.distribution = MicrofacetType::Beckmann;
    const MetalRoughBsdf expected(p);
    const Vec3 wo = b.frame.to_local(wo_world), wi = spherical_direction(0.5f, 2.0f);
    EXPECT_EQ(b.bsdf.get()->eval(wo, wi, Transport::Radiance),
              expected.eval(wo, wi, Transport::Radiance));
    EXPECT_NE(g.bsdf.get()->eval(wo, wi, Transport::Radiance),
              expected.eval(wo, wi, Transport::Radiance));
}

TEST(Shade, BeckmannGltfMaterialSamplesFollowThePdf) {
    // The glTF BRDF with Beckmann instead of GGX (the --microfacet switch): its sampling
    // must still match its pdf, and as a metal it must not gain energy. (The spec's
    // dielectric base gains energy at grazing angles with either distribution; see
    // metal_rough_bsdf_test.cpp. Narrow Beckmann lobes, which the sphere quadrature
    // cannot resolve, are tested by half vector in cook_torrance_test.cpp.)
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    const float roughness[] = {0.3f, 0.6f, 1.0f};
    const float cos_os[] = {0.9f, 0.05f};
    MaterialOptions beckmann;
    beckmann.gltf_distribution = MicrofacetType::Beckmann;
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, std::size(roughness) * std::size(cos_os));
    int seed = 700;
    for (float r : roughness)
        for (float cos_o : cos_os) {
            m.roughness = r;
            m.metallic = cos_o < 0.5f ? 1.0f : 0.3f;  // a grazing metal, a dielectric mix
            const Scene scene = scene_with(m);
            const Vec3 wo_world = spherical_direction(cos_o, 0.3f);
            const ShadingData sd = shade(scene, flat_point(0), wo_world, beckmann);
            const Vec3 wo = sd.frame.to_local(wo_world);
            o.seed = ++seed;
            const test::Chi2Result c = test::bsdf_chi2(*sd.bsdf.get(), wo, o);
            EXPECT_TRUE(c.passed) << "roughness " << r << ", cos_o " << cos_o << "\n" << c.report;
            if (m.metallic < 1) continue;
            const test::AlbedoEstimate a = test::directional_albedo(*sd.bsdf.get(), wo, 20000, 21);
            EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + 1e-5f) << "roughness " << r;
        }
}

TEST(Shade, TextureTransformMovesLookups) {
    // A 2 x 2 texture: red, green on top; blue, white below. Nearest filtering.
    Scene scene;
    Image img(2, 2, 4);
    const float texels[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 4; ++c) img.at(i % 2, i / 2)[c] = texels[i][c];
    scene.images.push_back(TextureImage(img));
    Texture tex;
    tex.nearest = true;
    scene.textures.push_back(tex);
    MaterialDesc m;
    m.metallic = 0;
    m.specular = 0;
    m.base_color_texture.texture = 0;
    m.emissive = {1, 1, 1};
    m.emissive_texture.texture = 0;
    scene.materials.push_back(m);
    const Vec3 up(0, 0, 1);
    // Untransformed, uv (0.25, 0.25) reads red.
    EXPECT_EQ(shade(scene, flat_point(0), up).base_color, Spectrum(1, 0, 0));
    // Offset by half a texture in u: green; in v too: white. Emission follows.
    scene.materials[0].base_color_texture.offset = {0.5f, 0};
    scene.materials[0].emissive_texture.offset = {0.5f, 0.5f};
    EXPECT_EQ(shade(scene, flat_point(0), up).base_color, Spectrum(0, 1, 0));
    EXPECT_EQ(shade(scene, flat_point(0), up).emission, Spectrum(1, 1, 1));
    EXPECT_EQ(emitted_radiance(scene, scene.materials[0], {0.25f, 0.25f}, {0, 0}),
              Spectrum(1, 1, 1));
    // The texCoord override selects the second UV set.
    scene.materials[0].base_color_texture.offset = {0, 0};
    scene.materials[0].base_color_texture.texcoord = 1;
    SurfacePoint sp = flat_point(0);
    sp.uv1 = {0.25f, 0.75f};
    EXPECT_EQ(shade(scene, sp, up).base_color, Spectrum(0, 0, 1));
}

TEST(TextureRef, TransformFollowsTheExtensionSpec) {
    // The spec's example: offset (0, 1), rotation 90 degrees, scale 0.5 "utilizes only
    // the lower left quadrant of the source image, rotated clockwise 90 degrees".
    TextureRef r;
    r.offset = {0, 1};
    r.rotation = kPi / 2;
    r.scale = {0.5f, 0.5f};
    const Vec2 corners[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (Vec2 c : corners) {
        const Vec2 t = r.uv(c, {0, 0});
        EXPECT_GE(t.x, -1e-6f);
        EXPECT_LE(t.x, 0.5f + 1e-6f);
        EXPECT_GE(t.y, 0.5f - 1e-6f);
        EXPECT_LE(t.y, 1 + 1e-6f);
    }
    // u' = cos x + sin y, v' = -sin x + cos y, on scaled coordinates, then offset.
    const Vec2 t = r.uv({1, 0}, {0, 0});
    EXPECT_NEAR(t.x, 0.0f, 1e-6f);
    EXPECT_NEAR(t.y, 0.5f, 1e-6f);
    // The second example flips v: offset (0, 1), scale (1, -1).
    TextureRef flip;
    flip.offset = {0, 1};
    flip.scale = {1, -1};
    EXPECT_NEAR(flip.uv({0.3f, 0.2f}, {0, 0}).y, 0.8f, 1e-6f);
    EXPECT_NEAR(flip.uv({0.3f, 0.2f}, {0, 0}).x, 0.3f, 1e-6f);
}

}  // namespace
}  // namespace penumbra
