// Bsdf::eval_diffuse: the diffuse lobes' share of eval, which the bump shadowing term
// darkens. It is all of a Lambertian's eval, none of a metal's or a glass's, and for the
// glTF dielectric exactly what a black base colour takes away (the specular lobe does
// not depend on the base colour).
#include <gtest/gtest.h>

#include "core/sampling/rng.h"
#include "materials/material.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

SurfacePoint flat_point(int material) {
    SurfacePoint sp;
    sp.ng = sp.ns = Vec3(0, 0, 1);
    sp.dpdu = Vec3(1, 0, 0);
    sp.material = material;
    return sp;
}

struct Parts {
    Spectrum f, fd;
};

// eval and eval_diffuse of material m's BSDF at a flat hit seen from wo.
Parts parts(const MaterialDesc& m, Vec3 wo, Vec3 wi) {
    Scene scene;
    scene.materials.push_back(m);
    const ShadingData sd = shade(scene, flat_point(0), wo);
    const Bsdf& b = *sd.bsdf.get();
    return {b.eval(wo, wi, Transport::Radiance), b.eval_diffuse(wo, wi, Transport::Radiance)};
}

MaterialDesc dielectric(Spectrum base) {
    MaterialDesc m;
    m.base_color = {base.x, base.y, base.z, 1};
    m.metallic = 0;
    m.roughness = 0.5f;
    return m;
}

TEST(EvalDiffuse, IsTheDiffuseShareOfEval) {
    Rng rng(7);
    MaterialDesc lambert = dielectric(Spectrum(0.8f));
    lambert.specular = 0;
    MaterialDesc metal = dielectric(Spectrum(0.9f));
    metal.metallic = 1;
    MaterialDesc glass = dielectric(Spectrum(1));
    glass.transmission = 1;
    MaterialDesc coated = dielectric(Spectrum(0.8f));
    coated.clearcoat = 1;
    coated.clearcoat_roughness = 0.3f;
    MaterialDesc translucent = dielectric(Spectrum(0.8f));
    translucent.diffuse_transmission = 0.5f;
    const Spectrum base(0.8f, 0.5f, 0.2f);
    for (int i = 0; i < 200; ++i) {
        const Vec3 wo = test::random_direction(rng), wi = test::random_direction(rng);
        const Parts l = parts(lambert, wo, wi);
        EXPECT_EQ(l.fd, l.f);
        const Parts me = parts(metal, wo, wi);
        EXPECT_GT(max_component(me.f), 0);
        EXPECT_EQ(me.fd, Spectrum(0));
        EXPECT_EQ(parts(glass, wo, wi).fd, Spectrum(0));
        // The dielectric: f minus its diffuse share is the black-based one's f.
        const Parts d = parts(dielectric(base), wo, wi);
        const Parts black = parts(dielectric(Spectrum(0)), wo, wi);
        EXPECT_EQ(black.fd, Spectrum(0));
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(d.fd[c], 0) << i;
            EXPECT_NEAR(d.f[c] - d.fd[c], black.f[c], 1e-5f * (1 + black.f[c])) << i;
        }
        // Under a coat (and with diffuse transmission) still a part of eval, and the
        // coat lets less of the base through.
        for (const MaterialDesc* m : {&coated, &translucent}) {
            const Parts p = parts(*m, wo, wi);
            for (int c = 0; c < 3; ++c) {
                EXPECT_GT(p.fd[c], 0) << i;
                EXPECT_LE(p.fd[c], p.f[c] * (1 + 1e-6f)) << i;
            }
        }
        const Parts under = parts(coated, wo, wi), bare = parts(dielectric(Spectrum(0.8f)), wo, wi);
        EXPECT_LE(under.fd.x, bare.fd.x * (1 + 1e-6f)) << i;
    }
}

}  // namespace
}  // namespace penumbra
