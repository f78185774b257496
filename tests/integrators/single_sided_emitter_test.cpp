// A square emitter above a Lambertian floor, facing it or away, single- or double-sided,
// placed directly, through a mirroring instance or a mirrored glTF node: every integrator
// and light strategy sees the floor lit by the analytic irradiance or exactly black.
#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/embree_accel.h"
#include "integrators/integrator.h"
#include "io/gltf/gltf_loader.h"
#include "support/statistics/estimate.h"
#include "support/gltf_builder.h"
#include "support/irradiance.h"
#include "support/scene_builder.h"
#include "support/option_names.h"

namespace penumbra {
namespace {

using test::square_irradiance;

const float kAlbedo = 0.5f, kLe = 2, kSide = 1, kHeight = 1;

struct Setup {
    Scene scene;
    std::unique_ptr<EmbreeAccel> accel;
    std::unique_ptr<LightSet> lights;
};

// The floor y = 0 (facing up) and the emitter, the square [-s/2, s/2]^2 in x and z,
// object-space front +Y (counter-clockwise from above), placed by `xf`.
std::unique_ptr<Setup> floor_and_emitter(bool double_sided, const Transform& xf,
                                         const LightSetOptions& lights = {}) {
    auto s = std::make_unique<Setup>();
    const int floor = test::add_lambertian(s->scene, Spectrum(kAlbedo));
    const int emitter = test::add_lambertian(s->scene, Spectrum(0));
    s->scene.materials[emitter].emissive = Spectrum(kLe);
    s->scene.materials[emitter].double_sided = double_sided;
    test::add_instance(s->scene,
                       test::add_quad_object(s->scene, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20},
                                             {-20, 0, -20}, floor),
                       Transform());
    const float h = kSide / 2;
    test::add_instance(
        s->scene,
        test::add_quad_object(s->scene, {-h, 0, -h}, {-h, 0, h}, {h, 0, h}, {h, 0, -h}, emitter),
        xf);
    s->accel = std::make_unique<EmbreeAccel>(s->scene);
    s->lights = std::make_unique<LightSet>(s->scene, nullptr, lights);
    return s;
}

struct Config {
    const char* name;
    std::string integrator;
    IntegratorOptions options;
};

std::vector<Config> configs() {
    std::vector<Config> c;
    for (auto [name, strategy] : {std::pair{"path mis", LightStrategy::Mis},
                                  {"path bsdf", LightStrategy::BsdfOnly},
                                  {"path light", LightStrategy::LightOnly}}) {
        IntegratorOptions o;
        o.strategy = strategy;
        c.push_back({name, "path", o});
    }
    for (auto [name, nl, nb] :
         {std::tuple{"direct 1+1", 1, 1}, {"direct 4+0", 4, 0}, {"direct 0+4", 0, 4}}) {
        IntegratorOptions o;
        o.light_samples = nl;
        o.bsdf_samples = nb;
        c.push_back({name, "direct", o});
    }
    return c;
}

// Radiance of the floor point under the emitter's centre, seen from straight above it
// (from below the emitter).
test::Estimate floor_radiance(const Setup& s, const Config& c, uint64_t n) {
    const auto integrator = make_integrator(test::integrator_named(c.integrator), c.options);
    auto sampler = make_sampler(SamplerType::Independent, 1, 5);
    const RenderContext ctx{s.scene, *s.accel, *s.lights};
    return test::estimate(n, [&](uint64_t i) {
        sampler->start_pixel_sample({int(i), 0}, 0);
        Ray r;
        r.o = {0, 0.5f * kHeight, 0};
        r.d = {0, -1, 0};
        return integrator->Li(r, ctx, *sampler).y;
    });
}

// The emitter's face seen from `eye` straight along Y (through its centre), by a ray that
// meets its back as a bounce does (camera rays pass through it: CameraCullingRender).
float seen_emitter(const Setup& s, const std::string& integrator, float eye_y) {
    const auto integ = make_integrator(test::integrator_named(integrator), {});
    auto sampler = make_sampler(SamplerType::Independent, 1, 5);
    RenderContext ctx{s.scene, *s.accel, *s.lights};
    ctx.camera_culling = false;
    sampler->start_pixel_sample({0, 0}, 0);
    Ray r;
    r.o = {0.01f, eye_y, 0.02f};
    r.d = {0, eye_y > kHeight ? -1.0f : 1.0f, 0};
    return integ->Li(r, ctx, *sampler).y;
}

const Transform kFacingDown =
    Transform::translate({0, kHeight, 0}) * Transform::rotate({1, 0, 0, 0});  // half turn
const Transform kFacingUp = Transform::translate({0, kHeight, 0});
// Mirrored through its plane: the world winding faces up, glTF's front face down.
const Transform kMirroredDown =
    Transform::translate({0, kHeight, 0}) * Transform::scale({1, -1, 1});
// Mirrored within its plane: the world winding faces down, glTF's front face up.
const Transform kMirroredUp = Transform::translate({0, kHeight, 0}) * Transform::scale({-1, 1, 1});

// The light selections and triangle strategies of --light-sampler and
// --triangle-sampling (the defaults, power and area, are tested below as well).
TEST(SingleSidedEmitter, EveryLightSelectionGivesTheAnalyticIrradiance) {
    const double expected = kAlbedo / kPi * square_irradiance(kLe, kSide, kHeight);
    for (LightSamplerType type :
         {LightSamplerType::Uniform, LightSamplerType::Power, LightSamplerType::Bvh})
        for (TriangleSampling ts : {TriangleSampling::Area, TriangleSampling::SolidAngle}) {
            const auto s = floor_and_emitter(false, kFacingDown, {type, ts});
            for (const Config& c : configs()) {
                if (c.name != std::string("path mis") && c.name != std::string("path light"))
                    continue;
                const test::Estimate e = floor_radiance(*s, c, 60000);
                EXPECT_TRUE(test::within(e, expected))
                    << int(type) << " " << int(ts) << ", " << c.name << ": " << e.mean
                    << " +- " << e.std_error << ", expected " << expected;
                EXPECT_LT(e.std_error, 0.01 * expected) << c.name;
            }
        }
}

TEST(SingleSidedEmitter, FacingTheFloorGivesTheAnalyticIrradiance) {
    const double expected = kAlbedo / kPi * square_irradiance(kLe, kSide, kHeight);
    struct Case {
        const char* name;
        bool double_sided;
        Transform xf;
    };
    for (const Case& k : {Case{"facing down", false, kFacingDown},
                          Case{"mirrored, front down", false, kMirroredDown},
                          Case{"double-sided, facing up", true, kFacingUp}}) {
        const auto s = floor_and_emitter(k.double_sided, k.xf);
        for (const Config& c : configs()) {
            const test::Estimate e = floor_radiance(*s, c, 60000);
            EXPECT_TRUE(test::within(e, expected))
                << k.name << ", " << c.name << ": " << e.mean << " +- " << e.std_error
                << ", expected " << expected;
            // Power: a 5% error (a one-sided density off by a cosine's sign would be far
            // more) stands out by 5 standard errors.
            EXPECT_LT(e.std_error, 0.01 * expected) << k.name << ", " << c.name;
        }
    }
}

TEST(SingleSidedEmitter, FacingAwayLeavesTheFloorBlack) {
    for (const auto& [name, xf] :
         {std::pair{"facing up", kFacingUp}, {"mirrored, front up", kMirroredUp}}) {
        const auto s = floor_and_emitter(false, xf);
        for (const Config& c : configs()) {
            const test::Estimate e = floor_radiance(*s, c, 2000);
            EXPECT_EQ(e.mean, 0.0) << name << ", " << c.name;
        }
    }
}

// The floor and the emitter (a counter-clockwise quad, radiance 1) in a glTF file whose
// emitter node has the scale `scale`, at height kHeight.
std::unique_ptr<Setup> gltf_floor_and_emitter(const test::ScratchDir& dir, const char* name,
                                              const std::string& scale) {
    test::GltfBuilder b;
    const float h = kSide / 2;
    b.add(std::vector<float>{-20, 0, 20, 20, 0, 20, 20, 0, -20, -20, 0, -20}, test::kFloat, "VEC3");
    b.add(std::vector<float>{-h, 0, -h, -h, 0, h, h, 0, h, h, 0, -h}, test::kFloat, "VEC3");
    b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUShort, "SCALAR");
    const std::string a = std::to_string(kAlbedo);
    const std::string members = R"("extensionsUsed": ["KHR_materials_specular"],
      "materials": [
        {"pbrMetallicRoughness": {"baseColorFactor": [)" +
                                a + "," + a + "," + a +
                                R"(, 1], "metallicFactor": 0},
         "extensions": {"KHR_materials_specular": {"specularFactor": 0}}},
        {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
         "emissiveFactor": [1, 1, 1],
         "extensions": {"KHR_materials_specular": {"specularFactor": 0}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "material": 0}]},
                 {"primitives": [{"attributes": {"POSITION": 1}, "indices": 2, "material": 1}]}],
      "nodes": [{"mesh": 0}, {"mesh": 1, "translation": [0, 1, 0], "scale": )" +
                                scale + R"(}],
      "scenes": [{"nodes": [0, 1]}], "scene": 0)";
    auto s = std::make_unique<Setup>();
    s->scene = load_gltf(b.write(dir, name, members, test::BufferStorage::DataUri));
    s->accel = std::make_unique<EmbreeAccel>(s->scene);
    s->lights = std::make_unique<LightSet>(s->scene, nullptr);
    return s;
}

TEST(SingleSidedEmitter, GltfNodeWithNegativeDeterminantFlipsTheFrontFace) {
    // glTF 2.0, 3.7.2.1: under a negative determinant the clockwise face is the front.
    ASSERT_EQ(kHeight, 1.0f);  // the file's translation
    const test::ScratchDir dir;
    const double lit = kAlbedo / kPi * square_irradiance(1, kSide, kHeight);
    const Config path_mis = configs()[0];
    const auto through_plane = gltf_floor_and_emitter(dir, "down.gltf", "[1, -1, 1]");
    const test::Estimate e = floor_radiance(*through_plane, path_mis, 60000);
    EXPECT_TRUE(test::within(e, lit)) << e.mean << " +- " << e.std_error << ", expected " << lit;
    const auto in_plane = gltf_floor_and_emitter(dir, "up.gltf", "[-1, 1, 1]");
    EXPECT_EQ(floor_radiance(*in_plane, path_mis, 2000).mean, 0.0);
    const auto unmirrored = gltf_floor_and_emitter(dir, "plain.gltf", "[1, 1, 1]");
    EXPECT_EQ(floor_radiance(*unmirrored, path_mis, 2000).mean, 0.0);
}

TEST(SingleSidedEmitter, SeenFromBehindItIsBlackFromTheFrontItIsLe) {
    // The emitter's own BSDF is black, so what a camera ray sees of it is emission only.
    for (bool double_sided : {false, true}) {
        const auto s = floor_and_emitter(double_sided, kFacingDown);
        for (const char* integrator : {"basic", "direct", "path"}) {
            EXPECT_EQ(seen_emitter(*s, integrator, 0.5f * kHeight), kLe) << integrator;
            EXPECT_EQ(seen_emitter(*s, integrator, 2 * kHeight), double_sided ? kLe : 0.0f)
                << integrator << (double_sided ? ", double-sided" : ", single-sided");
        }
    }
}

}  // namespace
}  // namespace penumbra
