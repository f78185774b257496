// A render written with AOVs and read back with OIIO: layer and channel names, AOV
// values on a scene with known answers, header metadata (camera matrices, colour space,
// chromaticities, error against a reference), half against float, compression.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <map>

#include "core/accel/embree_accel.h"
#include "core/camera/camera_matrices.h"
#include "core/error.h"
#include "core/lights/directional_light.h"
#include "integrators/render.h"
#include "io/image/image_reader.h"
#include "io/image/render_writer.h"
#include "support/gltf_builder.h"
#include "support/scene_builder.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

using test::ScratchDir;

const Spectrum kAlbedo(0.25f, 0.5f, 0.75f);
constexpr int kW = 16, kH = 8;
constexpr uint32_t kSpp = 4;

// A Lambertian square [-1.5, 1.5]^2 at z = 0 facing +Z, seen by an orthographic camera
// 5 units away on +Z whose view is 4 x 2 units: the columns beyond |x| = 1.5 miss.
struct PlaneScene {
    Scene scene;
    CameraDesc camera;
    PlaneScene() {
        const int mat = test::add_lambertian(scene, kAlbedo);
        const uint32_t quad = test::add_quad_object(scene, {-1.5f, -1.5f, 0}, {1.5f, -1.5f, 0},
                                                    {1.5f, 1.5f, 0}, {-1.5f, 1.5f, 0}, mat);
        test::add_instance(scene, quad, Transform());
        scene.lights.push_back(
            std::make_unique<DirectionalLight>(normalize(Vec3(0.3f, 0, -1)), Spectrum(2.0f), 10));
        camera.name = "ortho";
        camera.type = ProjectionType::Orthographic;
        camera.ymag = 1;
        camera.znear = 0.1f;
        camera.to_world = Transform::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
    }
};

Film render_plane(const PlaneScene& p, AovSet aovs, int threads = 0) {
    EmbreeAccel accel(p.scene);
    const LightSet lights(p.scene, nullptr);
    const RenderContext ctx{p.scene, accel, lights};
    const std::unique_ptr<Camera> camera = make_camera(p.camera, kW, kH);
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = kSpp;
    opt.progress = false;
    opt.aovs = aovs;
    opt.threads = threads;
    return render(ctx, *camera, *integrator, opt);
}

// Every channel of an EXR by name, and its spec.
struct Exr {
    OIIO::ImageSpec spec;
    std::map<std::string, std::vector<float>> channels;
    float at(const std::string& c, int x, int y) const {
        return channels.at(c)[size_t(y) * spec.width + x];
    }
};

Exr read_exr(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    Exr e;
    if (!in) return e;
    e.spec = in->spec();
    const size_t n = size_t(e.spec.width) * e.spec.height;
    std::vector<float> all(n * e.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, e.spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()));
    for (int c = 0; c < e.spec.nchannels; ++c) {
        std::vector<float>& v = e.channels[e.spec.channelnames[c]];
        for (size_t i = 0; i < n; ++i) v.push_back(all[i * e.spec.nchannels + c]);
    }
    return e;
}

TEST(ExrAov, LayersReadBackWithTheirNamesAndValues) {
    ScratchDir dir;
    const PlaneScene p;
    const Film film = render_plane(p, parse_aovs("all"));
    RenderFiles files;
    files.exr = dir.file("plane.exr");
    write_render(files, film, ColorPipeline::builtin(), p.camera, {{"penumbra:spp", "4"}});
    const Exr e = read_exr(files.exr);
    std::vector<std::string> names;
    for (const auto& [name, values] : e.channels) names.push_back(name);
    const std::vector<std::string> expected = {
        "A",        "Albedo.B",   "Albedo.G",     "Albedo.R",   "B",
        "Depth.Z",  "G",          "MaterialID.X", "Normal.X",   "Normal.Y",
        "Normal.Z", "ObjectID.X", "Position.X",   "Position.Y", "Position.Z",
        "R",        "Samples.X",  "Variance.B",   "Variance.G", "Variance.R",
        "Vector.W", "Vector.X",   "Vector.Y",     "Vector.Z"};
    EXPECT_EQ(names, expected);
    // The IDs are 32-bit floats holding integers.
    EXPECT_EQ(e.spec.channelformat(e.spec.channelindex("ObjectID.X")), OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(e.spec.alpha_channel, e.spec.channelindex("A"));

    // The plane's columns: pixel x covers world [-2 + x/4, -2 + (x+1)/4].
    for (int y = 0; y < kH; ++y)
        for (int x = 3; x <= 12; ++x) {
            EXPECT_NEAR(e.at("Albedo.R", x, y), kAlbedo.x, 1e-6f);
            EXPECT_NEAR(e.at("Albedo.G", x, y), kAlbedo.y, 1e-6f);
            EXPECT_NEAR(e.at("Albedo.B", x, y), kAlbedo.z, 1e-6f);
            EXPECT_NEAR(e.at("Normal.Z", x, y), 1, 1e-6f);
            EXPECT_NEAR(e.at("Normal.X", x, y), 0, 1e-6f);
            EXPECT_NEAR(e.at("Depth.Z", x, y), 5, 1e-5f);
            EXPECT_NEAR(e.at("Position.Z", x, y), 0, 1e-6f);
            // Filtered positions stay near the pixel centre (the filter reaches 1.5 px).
            EXPECT_NEAR(e.at("Position.X", x, y), -2 + (x + 0.5f) / 4, 1.5f / 4);
            EXPECT_EQ(e.at("Samples.X", x, y), float(kSpp));
            EXPECT_GE(e.at("Variance.R", x, y), 0);
            EXPECT_EQ(e.at("MaterialID.X", x, y), 0.0f);  // the plane's material
            // A scene loaded without its neighbouring frames has no motion.
            EXPECT_EQ(e.at("Vector.X", x, y), 0.0f);
        }
    // Beyond the plane: nothing hit.
    for (int y = 0; y < kH; ++y)
        for (int x : {0, 15}) {
            EXPECT_EQ(e.at("Depth.Z", x, y), Film::kNoHitDepth);
            EXPECT_EQ(e.at("Albedo.R", x, y), 0);
            EXPECT_EQ(e.at("Samples.X", x, y), float(kSpp));
            EXPECT_EQ(e.at("MaterialID.X", x, y), float(kNoHitId));
            EXPECT_EQ(e.at("ObjectID.X", x, y), float(kNoHitId));
        }
    // The beauty channels hold the film's beauty.
    const Image beauty = film.resolve();
    EXPECT_EQ(e.at("R", 7, 3), beauty.at(7, 3)[0]);
    EXPECT_EQ(e.at("A", 7, 3), 1.0f);
    // read_image (and so a --reference) finds the beauty among the layers.
    const Image back = read_image(files.exr, ImageEncoding::Linear);
    ASSERT_EQ(back.channels, 4);
    EXPECT_EQ(back.at(7, 3)[0], beauty.at(7, 3)[0]);
    EXPECT_EQ(back.at(7, 3)[2], beauty.at(7, 3)[2]);
}

TEST(ExrAov, HeaderDescribesCameraAndColour) {
    ScratchDir dir;
    const PlaneScene p;
    RenderFiles files;
    files.exr = dir.file("plane.exr");
    write_render(files, render_plane(p, {}), ColorPipeline::builtin(), p.camera,
                 {{"penumbra:seed", "7"}, {"penumbra:render_seconds", 1.5f}});
    const OIIO::ImageSpec spec = read_exr(files.exr).spec;
    EXPECT_EQ(spec.nchannels, 4);  // no AOVs asked for
    EXPECT_EQ(spec.get_string_attribute("penumbra:seed"), "7");
    EXPECT_EQ(spec.get_float_attribute("penumbra:render_seconds"), 1.5f);
    EXPECT_EQ(spec.get_string_attribute("penumbra:camera"), "ortho");
    EXPECT_EQ(spec.get_string_attribute("penumbra:colorspace"), "Linear Rec.709 (sRGB)");
    EXPECT_EQ(spec.get_string_attribute("compression"), "zip");

    const OIIO::ParamValue* chroma = spec.find_attribute("chromaticities");
    ASSERT_TRUE(chroma);
    ASSERT_EQ(chroma->type(), OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
    const float* c = static_cast<const float*>(chroma->data());
    const float rec709[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(c[i], rec709[i], 1e-6f) << i;

    // Imath matrices multiply row vectors: the world origin is 5 units ahead (+Z).
    for (const char* name : {"worldtocamera", "worldtoNDC"}) {
        const OIIO::ParamValue* m = spec.find_attribute(name);
        ASSERT_TRUE(m) << name;
        ASSERT_EQ(m->type(), OIIO::TypeMatrix44) << name;
    }
    const float* w2c = static_cast<const float*>(spec.find_attribute("worldtocamera")->data());
    EXPECT_NEAR(w2c[12], 0, 1e-6f);
    EXPECT_NEAR(w2c[14], 5, 1e-6f);
    // World (1, 0.5, 0) lies at NDC x = (1 + 2) / 4, y = (1 - 0.5) / 2.
    const float* ndc = static_cast<const float*>(spec.find_attribute("worldtoNDC")->data());
    const float px = 1, py = 0.5f, pz = 0;
    float q[4];
    for (int j = 0; j < 4; ++j)
        q[j] = px * ndc[j] + py * ndc[4 + j] + pz * ndc[8 + j] + ndc[12 + j];
    EXPECT_NEAR(q[0] / q[3], 0.75f, 1e-6f);
    EXPECT_NEAR(q[1] / q[3], 0.25f, 1e-6f);
}

TEST(ExrAov, AcescgOutputConvertsBeautyAndAlbedoAndTagsAp1) {
    ScratchDir dir;
    const PlaneScene p;
    const Film film = render_plane(p, parse_aovs("albedo,normal"));
    ColorSettings cs;
    cs.config = "builtin";
    cs.output_space = "ACEScg";
    const ColorPipeline color(cs);
    RenderFiles files;
    files.exr = dir.file("cg.exr");
    write_render(files, film, color, p.camera, {});
    const Exr e = read_exr(files.exr);
    EXPECT_EQ(e.spec.get_string_attribute("penumbra:colorspace"), "ACEScg");
    const float* c = static_cast<const float*>(e.spec.find_attribute("chromaticities")->data());
    EXPECT_NEAR(c[0], 0.713f, 1e-6f);
    EXPECT_NEAR(c[6], 0.32168f, 1e-6f);
    float albedo[3] = {kAlbedo.x, kAlbedo.y, kAlbedo.z};
    color.convert(albedo, 1, "Linear Rec.709 (sRGB)", "ACEScg");
    EXPECT_NEAR(e.at("Albedo.R", 8, 4), albedo[0], 1e-6f);
    EXPECT_NEAR(e.at("Albedo.B", 8, 4), albedo[2], 1e-6f);
    EXPECT_NEAR(e.at("Normal.Z", 8, 4), 1, 1e-6f);  // data is not converted
    Image beauty = film.resolve();
    color.to_output(beauty);
    EXPECT_EQ(e.at("G", 8, 4), beauty.at(8, 4)[1]);
}

TEST(ExrAov, HalfKeepsDataInFloatAndRoundTripsColour) {
    ScratchDir dir;
    const PlaneScene p;
    const Film film = render_plane(p, parse_aovs("all"));
    RenderFiles files;
    files.exr = dir.file("float.exr");
    write_render(files, film, ColorPipeline::builtin(), p.camera, {});
    files.exr = dir.file("half.exr");
    files.exr_options.half = true;
    files.exr_options.compression = "piz";
    write_render(files, film, ColorPipeline::builtin(), p.camera, {});
    const Exr f = read_exr(dir.file("float.exr")), h = read_exr(dir.file("half.exr"));
    EXPECT_EQ(f.spec.format, OIIO::TypeDesc::FLOAT);
    EXPECT_TRUE(f.spec.channelformats.empty());
    EXPECT_EQ(h.spec.get_string_attribute("compression"), "piz");
    ASSERT_EQ(h.spec.channelformats.size(), size_t(h.spec.nchannels));
    auto format = [&](const char* c) { return h.spec.channelformats[h.spec.channelindex(c)]; };
    EXPECT_EQ(format("R"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(format("Albedo.G"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(format("Normal.X"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(format("Depth.Z"), OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(format("Position.Y"), OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(format("Samples.X"), OIIO::TypeDesc::FLOAT);
    for (const auto& [name, values] : f.channels)
        for (size_t i = 0; i < values.size(); ++i) {
            const float a = values[i], b = h.channels.at(name)[i];
            if (format(name.c_str()) == OIIO::TypeDesc::FLOAT)
                ASSERT_EQ(a, b) << name;
            else  // half: 11 significant bits
                ASSERT_NEAR(a, b, std::abs(a) * 1e-3f + 1e-7f) << name;
        }
}

TEST(ExrAov, CompressionIsSelectable) {
    ScratchDir dir;
    Image img(4, 4, 4);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = float(i % 7) / 7;
    const ExrLayer beauty{"", {"R", "G", "B", "A"}, &img, false};
    for (const char* c : {"none", "rle", "zip", "piz", "pxr24", "b44", "dwaa"}) {
        ExrOptions o;
        o.compression = c;
        write_exr(dir.file("c.exr"), {beauty}, {}, o);
        EXPECT_EQ(read_exr(dir.file("c.exr")).spec.get_string_attribute("compression"), c);
    }
    ExrOptions bad;
    bad.compression = "lzma";
    EXPECT_THROW(write_exr(dir.file("c.exr"), {beauty}, {}, bad), SceneError);
}

TEST(ExrAov, ReferenceGivesMseAndRelMse) {
    ScratchDir dir;
    Film film(2, 1);
    film.add_sample(0, 0, {1, 2, 3}, 1);
    film.add_sample(1, 0, {0, 0.5f, 1}, 1);
    Image ref(2, 1, 3);
    ref.pixels = {1, 1, 1, 0, 0, 0};
    write_exr(dir.file("ref.exr"), ref);
    RenderFiles files;
    files.exr = dir.file("x.exr");
    files.reference = dir.file("ref.exr");
    CameraDesc cam;
    const RenderFilesResult r = write_render(files, film, ColorPipeline::builtin(), cam, {});
    // Squared errors 0, 1, 4 and 0, 0.25, 1 over six values.
    const double mse = (0 + 1 + 4 + 0 + 0.25 + 1) / 6.0;
    const double relmse = (0 + 1 / 1.01 + 4 / 1.01 + 0 + 0.25 / 0.01 + 1 / 0.01) / 6.0;
    ASSERT_TRUE(r.mse && r.relmse);
    EXPECT_NEAR(*r.mse, mse, 1e-12);
    EXPECT_NEAR(*r.relmse, relmse, 1e-9);
    const OIIO::ImageSpec spec = read_exr(files.exr).spec;
    const OIIO::ParamValue* m = spec.find_attribute("penumbra:mse");
    ASSERT_TRUE(m);
    EXPECT_EQ(m->type(), OIIO::TypeDesc::DOUBLE);
    EXPECT_EQ(*static_cast<const double*>(m->data()), mse);
    EXPECT_NEAR(spec.get_float_attribute("penumbra:relmse_epsilon"), 0.01f, 1e-9f);

    Image wrong(3, 1, 3);
    write_exr(dir.file("wrong.exr"), wrong);
    files.reference = dir.file("wrong.exr");
    EXPECT_THROW(write_render(files, film, ColorPipeline::builtin(), cam, {}), SceneError);
}

}  // namespace
}  // namespace penumbra
