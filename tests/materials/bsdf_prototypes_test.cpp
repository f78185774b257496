// BsdfPrototypes: a material that is the same at every hit gets its model built once,
// and shade() with the prototypes gives bit for bit the BSDF it builds without them, at
// any hit (either side, any normal, any wo), under both distributions and layerings. A
// material that a texture, a vertex colour, the path or the frame can change gets none.
#include "materials/bsdf_prototypes.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

#include "core/math/frame.h"
#include "core/sampling/rng.h"
#include "io/gltf/gltf_loader.h"
#include "support/bsdf/bsdf_properties.h"
#include "support/paths.h"

namespace penumbra {
namespace {

MaterialDesc opaque(float metallic, float roughness) {
    MaterialDesc m;
    m.base_color = {0.7f, 0.5f, 0.3f, 1};
    m.metallic = metallic;
    m.roughness = roughness;
    return m;
}

// The uniform kinds shade() distinguishes: a bare Lambertian base, the layered
// dielectric (rough, smooth, tinted specular with another IOR), metals, a mirror, and
// an emitter.
std::vector<MaterialDesc> uniform_materials() {
    std::vector<MaterialDesc> out;
    MaterialDesc lambert = opaque(0, 0.5f);
    lambert.specular = 0;
    out.push_back(lambert);
    out.push_back(opaque(0, 1));
    out.push_back(opaque(0, 0.2f));
    MaterialDesc tinted = opaque(0, 0.4f);
    tinted.specular = 0.6f;
    tinted.specular_color = {1, 0.5f, 0.25f};
    tinted.ior = 1.8f;
    out.push_back(tinted);
    out.push_back(opaque(1, 0.05f));
    out.push_back(opaque(1, 0.6f));
    out.push_back(opaque(0.5f, 0.3f));
    out.push_back(opaque(1, 0));
    MaterialDesc emitter = opaque(0, 1);
    emitter.emissive = {1, 0.9f, 0.8f};
    emitter.emissive_strength = 4;
    out.push_back(emitter);
    return out;
}

bool same_bits(const Spectrum& a, const Spectrum& b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// shade() with and without prototypes at random hits: the same frame, emission and, for
// random directions, the same eval, pdf, eval_pdf and sample, bit for bit.
void expect_same_bsdf_at_random_hits(const Scene& scene, const MaterialOptions& options) {
    const BsdfPrototypes prototypes(scene, options);
    MaterialOptions with = options;
    with.prototypes = &prototypes;
    Rng rng(7);
    for (uint32_t mi = 0; mi < scene.materials.size(); ++mi) {
        SCOPED_TRACE("material " + std::to_string(mi));
        ASSERT_NE(prototypes.find(mi, Vec4(1, 1, 1, 1), options), nullptr);
        for (int hit = 0; hit < 20; ++hit) {
            SurfacePoint sp;
            sp.material = int(mi);
            sp.ng = test::random_direction(rng, 0.05f, hit % 2 == 1);
            sp.ns = normalize(sp.ng + test::random_direction(rng) * 0.2f);
            if (dot(sp.ns, sp.ng) <= 0) sp.ns = sp.ng;
            sp.dpdu = Frame::from_normal(sp.ng).s;
            const Vec3 wo_world = test::random_direction(rng, 0.05f, hit % 3 == 0);
            const ShadingData a = shade(scene, sp, wo_world, options);
            const ShadingData b = shade(scene, sp, wo_world, with);
            EXPECT_TRUE(same_bits(a.emission, b.emission));
            EXPECT_TRUE(same_bits(a.frame.n, b.frame.n));
            const Vec3 wo = a.frame.to_local(wo_world);
            for (int k = 0; k < 50; ++k) {
                const Vec3 wi = test::random_direction(rng, 0.01f, k % 5 == 0);
                const Transport mode = k % 2 ? Transport::Radiance : Transport::Importance;
                EXPECT_TRUE(same_bits(a.bsdf.get()->eval(wo, wi, mode),
                                      b.bsdf.get()->eval(wo, wi, mode)));
                EXPECT_TRUE(same_bits(a.bsdf.get()->pdf(wo, wi, mode),
                                      b.bsdf.get()->pdf(wo, wi, mode)));
                float pa, pb;
                const Spectrum fa = a.bsdf.get()->eval_pdf(wo, wi, mode, &pa);
                const Spectrum fb = b.bsdf.get()->eval_pdf(wo, wi, mode, &pb);
                EXPECT_TRUE(same_bits(fa, fb) && same_bits(pa, pb));
                const float u_lobe = rng.next_float();
                const Vec2 u(rng.next_float(), rng.next_float());
                const auto sa = a.bsdf.get()->sample(wo, u_lobe, u, mode);
                const auto sb = b.bsdf.get()->sample(wo, u_lobe, u, mode);
                ASSERT_EQ(bool(sa), bool(sb));
                if (sa) {
                    EXPECT_TRUE(same_bits(sa->wi.x, sb->wi.x) && same_bits(sa->wi.y, sb->wi.y) &&
                                same_bits(sa->wi.z, sb->wi.z));
                    EXPECT_TRUE(same_bits(sa->f, sb->f) && same_bits(sa->pdf, sb->pdf));
                }
            }
        }
    }
}

TEST(BsdfPrototypes, ShadeGivesTheSameBsdfBitForBitUnderEveryDistributionAndLayering) {
    Scene scene;
    scene.materials = uniform_materials();
    for (MicrofacetType d : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
        for (GltfLayering l : {GltfLayering::AlbedoScaled, GltfLayering::Spec}) {
            MaterialOptions options;
            options.gltf_distribution = d;
            options.gltf_layering = l;
            expect_same_bsdf_at_random_hits(scene, options);
        }
    }
}

// A hit refers to the prototype's model itself, of every kind, and copies of its
// ShadingData keep referring to it: no model keeps state between calls
// (MetalRoughBsdf's last wo's terms are per thread).
TEST(BsdfPrototypes, HitsShareThePrototypesModel) {
    Scene scene;
    scene.materials = uniform_materials();
    const MaterialOptions options;
    const BsdfPrototypes prototypes(scene, options);
    MaterialOptions with = options;
    with.prototypes = &prototypes;
    int metal_rough = 0;
    for (uint32_t mi = 0; mi < scene.materials.size(); ++mi) {
        SCOPED_TRACE("material " + std::to_string(mi));
        const BsdfStorage* proto = prototypes.find(mi, Vec4(1, 1, 1, 1), options);
        ASSERT_NE(proto, nullptr);
        SurfacePoint sp;
        sp.material = int(mi);
        sp.ng = sp.ns = Vec3(0, 0, 1);
        const ShadingData sd = shade(scene, sp, normalize(Vec3(0.3f, 0.2f, 1)), with);
        const ShadingData copy = sd;
        EXPECT_EQ(sd.bsdf.get(), proto->get());
        EXPECT_EQ(copy.bsdf.get(), proto->get());
        metal_rough += dynamic_cast<const MetalRoughBsdf*>(proto->get()) != nullptr;
    }
    EXPECT_GT(metal_rough, 0);
}

// One shared model asked by two threads at once, each about its own directions in its
// own order (so that each thread's wo changes from call to call as the other's does):
// every answer the same bits as one thread's alone. Terms cached in the model, not per
// thread, would let one thread's wo terms answer the other's questions.
TEST(BsdfPrototypes, ASharedModelAnswersEveryThreadAsOneThreadAlone) {
    Scene scene;
    scene.materials = {opaque(0, 0.3f), opaque(0.5f, 0.6f)};
    const BsdfPrototypes prototypes(scene, MaterialOptions{});
    for (uint32_t mi = 0; mi < scene.materials.size(); ++mi) {
        const Bsdf& bsdf = *prototypes.find(mi, Vec4(1, 1, 1, 1), MaterialOptions{})->get();
        ASSERT_NE(dynamic_cast<const MetalRoughBsdf*>(&bsdf), nullptr);
        struct Query {
            Vec3 wo, wi;
            Vec2 u;
            float u_lobe;
        };
        struct Answer {
            Spectrum f;
            float pdf;
            Vec3 wi;
            Spectrum weight;
        };
        Rng rng(11 + mi);
        std::vector<Query> queries(256);
        for (Query& q : queries) {
            q.wo = test::random_direction(rng, 0.02f, false);
            q.wi = test::random_direction(rng, 0.02f, false);
            q.u.x = rng.next_float();
            q.u.y = rng.next_float();
            q.u_lobe = rng.next_float();
        }
        auto answer = [&](const Query& q) {
            Answer a{};
            a.f = bsdf.eval_pdf(q.wo, q.wi, Transport::Radiance, &a.pdf);
            if (const auto s = bsdf.sample(q.wo, q.u_lobe, q.u, Transport::Radiance)) {
                a.wi = s->wi;
                a.weight = s->weight();
            }
            return a;
        };
        std::vector<Answer> alone(queries.size());
        for (size_t i = 0; i < queries.size(); ++i) alone[i] = answer(queries[i]);
        std::atomic<int> wrong{0};
        auto run = [&](size_t stride) {
            for (int round = 0; round < 200; ++round)
                for (size_t k = 0; k < queries.size(); ++k) {
                    const size_t i = (k * stride + round) % queries.size();
                    const Answer a = answer(queries[i]);
                    if (std::memcmp(&a, &alone[i], sizeof a) != 0) ++wrong;
                }
        };
        std::thread other(run, 3);
        run(5);
        other.join();
        EXPECT_EQ(wrong.load(), 0) << "material " << mi;
    }
}

TEST(BsdfPrototypes, NoneWhereATextureThePathOrTheFrameChangesTheModel) {
    std::vector<MaterialDesc> varying;
    const auto add = [&](auto change) {
        MaterialDesc m = opaque(0, 0.5f);
        change(m);
        varying.push_back(m);
    };
    add([](MaterialDesc& m) { m.base_color_texture.texture = 0; });
    add([](MaterialDesc& m) { m.metallic_roughness_texture.texture = 0; });
    add([](MaterialDesc& m) { m.specular_texture.texture = 0; });
    add([](MaterialDesc& m) { m.specular_color_texture.texture = 0; });
    add([](MaterialDesc& m) { m.transmission = 0.5f; });
    add([](MaterialDesc& m) { m.clearcoat = 1; });
    add([](MaterialDesc& m) { m.sheen_color = {0.5f, 0.5f, 0.5f}; });
    add([](MaterialDesc& m) { m.iridescence = 1; });
    add([](MaterialDesc& m) { m.anisotropy_strength = 0.5f; });
    add([](MaterialDesc& m) { m.diffuse_transmission = 0.5f; });
    add([](MaterialDesc& m) { m.unlit = true; });
    add([](MaterialDesc& m) { m.specular_glossiness = true; });
    Scene scene;
    scene.materials = varying;
    const MaterialOptions options;
    const BsdfPrototypes prototypes(scene, options);
    EXPECT_EQ(prototypes.count(), 0u);
    for (uint32_t i = 0; i < varying.size(); ++i) {
        EXPECT_FALSE(BsdfPrototypes::uniform(varying[i])) << i;
        EXPECT_EQ(prototypes.find(i, Vec4(1, 1, 1, 1), options), nullptr) << i;
    }
    // Maps that do not reach the model leave it uniform.
    MaterialDesc mapped = opaque(0, 0.5f);
    mapped.normal_texture.texture = 0;
    mapped.emissive_texture.texture = 0;
    mapped.occlusion_texture.texture = 0;
    EXPECT_TRUE(BsdfPrototypes::uniform(mapped));
}

TEST(BsdfPrototypes, FindRejectsAVertexColourOtherOptionsAndRegularizationAboveTheRoughness) {
    Scene scene;
    scene.materials = {opaque(0, 0.3f), opaque(1, 0)};
    const MaterialOptions options;
    const BsdfPrototypes prototypes(scene, options);
    EXPECT_EQ(prototypes.count(), 2u);
    EXPECT_NE(prototypes.find(0, Vec4(1, 1, 1, 1), options), nullptr);
    EXPECT_NE(prototypes.find(0, Vec4(1, 1, 1, 0.5f), options), nullptr);  // alpha: opacity only
    EXPECT_EQ(prototypes.find(0, Vec4(1, 0.5f, 1, 1), options), nullptr);
    EXPECT_EQ(prototypes.find(2, Vec4(1, 1, 1, 1), options), nullptr);
    EXPECT_EQ(prototypes.find(uint32_t(-1), Vec4(1, 1, 1, 1), options), nullptr);
    MaterialOptions other = options;
    other.gltf_distribution = MicrofacetType::Beckmann;
    EXPECT_EQ(prototypes.find(0, Vec4(1, 1, 1, 1), other), nullptr);
    other = options;
    other.gltf_layering = GltfLayering::Spec;
    EXPECT_EQ(prototypes.find(0, Vec4(1, 1, 1, 1), other), nullptr);
    MaterialOptions regularized = options;
    regularized.min_roughness = 0.3f;  // raises nothing on material 0
    EXPECT_NE(prototypes.find(0, Vec4(1, 1, 1, 1), regularized), nullptr);
    EXPECT_EQ(prototypes.find(1, Vec4(1, 1, 1, 1), regularized), nullptr);
    regularized.min_roughness = 0.31f;
    EXPECT_EQ(prototypes.find(0, Vec4(1, 1, 1, 1), regularized), nullptr);
}

TEST(BsdfPrototypes, EveryMaterialOfTheGlossySceneHasOneAndShadesTheSame) {
    const Scene scene = load_gltf(test::source_path("scenes/glossy.gltf"));
    const MaterialOptions options;
    EXPECT_EQ(BsdfPrototypes(scene, options).count(), scene.materials.size());
    expect_same_bsdf_at_random_hits(scene, options);
}

}  // namespace
}  // namespace penumbra
