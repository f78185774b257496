// Small glTF files for the material tests: one triangle carrying the materials under
// test and one texture over a 1x1 RGBA PNG whose texel tells a linear decode from an
// sRGB one.
#pragma once

#include <OpenImageIO/imageio.h>

#include <fstream>
#include <iterator>
#include <string>

#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"

namespace penumbra::test {

// The one texel of the test texture, as 8-bit codes: a linear decode gives code / 255,
// an sRGB one srgb_to_linear(code / 255) for RGB (0.2 -> 0.0331) and code / 255 for A.
inline constexpr unsigned char kTexel[4] = {51, 102, 204, 153};

inline std::string png_uri(const ScratchDir& dir, const unsigned char* texel = kTexel) {
    const std::string path = dir.file("t.png");
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(1, 1, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the file holds `texel` as given
    EXPECT_TRUE(out && out->open(path, spec));
    out->write_image(OIIO::TypeDesc::UINT8, texel);
    out->close();
    std::ifstream f(path, std::ios::binary);
    const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(f),
                                     std::istreambuf_iterator<char>()};
    return "data:image/png;base64," + test::base64(bytes);
}

// A textureInfo tagged k: texCoord k % 2 and a transform offset of k, so that each slot
// can be told apart from the others.
inline std::string tex(int k) {
    return R"({"index": 0, "texCoord": )" + std::to_string(k % 2) +
           R"(, "extensions": {"KHR_texture_transform": {"offset": [)" + std::to_string(k) +
           ", 0]}}}";
}

// Materials (JSON, where @k stands for tex(k)) on one triangle, with one texture over
// the test PNG.
inline Scene load_with_material(const std::string& materials,
                                const Mat3& to_working = Mat3::identity(), bool strict = false) {
    std::string json;
    for (size_t i = 0; i < materials.size(); ++i) {
        if (materials[i] != '@') {
            json += materials[i];
            continue;
        }
        size_t digits = 0;
        json += tex(std::stoi(materials.substr(i + 1), &digits));
        i += digits;
    }
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
    const std::string members =
        R"("extensionsUsed": ["KHR_texture_transform"],
        "images": [{"uri": ")" +
        png_uri(dir) + R"("}], "textures": [{"source": 0}],
        "materials": [)" +
        json + "],\n" + test::one_mesh_scene(R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 1}})");
    GltfLoadOptions options;
    options.rec709_to_working = to_working;
    options.strict = strict;
    return load_gltf(b.write(dir, "m.gltf", members, BufferStorage::DataUri), options);
}

}  // namespace penumbra::test
