// The AOV EXR round trip through Blender's compositor: Blender (Debian's blender, which
// scripts/setup.sh --test installs) opens penumbra's multi-channel EXR as a multilayer
// image whose compositor Image node offers every AOV as its own pass, under its name, and
// its Cryptomatte node decodes the Cryptomatte layers to the mattes of named objects and
// materials.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>
#include <string>

#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"
#include "support/paths.h"
#include "support/two_quads_scene.h"

namespace penumbra {
namespace {

std::string run_shell(const std::string& cmd) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((cmd + " 2>&1").c_str(), "r"), pclose);
    std::string out;
    std::array<char, 4096> buf;
    size_t n;
    while (pipe && (n = fread(buf.data(), 1, buf.size(), pipe.get())) > 0) out.append(buf.data(), n);
    return out;
}

// Loads the EXR into a compositor Image node and prints its passes as name:type.
constexpr const char* kScript = R"(import bpy, sys
path = sys.argv[sys.argv.index("--") + 1]
scene = bpy.context.scene
scene.use_nodes = True
node = scene.node_tree.nodes.new("CompositorNodeImage")
node.image = bpy.data.images.load(path)
print("IMAGE-TYPE", node.image.type)
print("PASSES", " ".join(o.name + ":" + o.type for o in node.outputs if o.enabled))
)";

TEST(BlenderRoundTrip, CompositorSeesEveryAovAsANamedPass) {
    // scripts/setup.sh --test (which scripts/test.sh runs) installs it.
    ASSERT_TRUE(std::filesystem::exists("/usr/bin/blender"))
        << "blender is not installed (Debian package blender; scripts/setup.sh --test)";
    const test::ScratchDir dir;
    const std::string exr = dir.file("aovs.exr");
    const test::CliResult r =
        test::run_penumbra({"render", test::source_path("scenes/cornell-box.gltf"), "-o", exr,
                            "--width", "16", "--spp", "2", "--aov", "all", "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string script = dir.write("passes.py", kScript);
    const std::string out = run_shell("/usr/bin/blender -b --factory-startup --python '" +
                                      script + "' -- '" + exr + "'");
    EXPECT_NE(out.find("IMAGE-TYPE MULTILAYER"), std::string::npos) << out;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(out, m, std::regex("PASSES ([^\\n]*)"))) << out;
    const std::string passes = " " + m[1].str() + " ";
    for (const char* p :
         {"Combined:RGBA", "Alpha:VALUE", "Albedo:RGBA", "Depth:VALUE", "Normal:RGBA",
          "Position:RGBA", "Variance:RGBA", "Samples:VALUE", "ObjectID:VALUE", "MaterialID:VALUE",
          "Vector:RGBA"})
        EXPECT_NE(passes.find(std::string(" ") + p + " "), std::string::npos)
            << p << " not among: " << passes;
}

// Renders the Cryptomatte layers' matte of `names` (comma-separated) through the
// compositor's Cryptomatte node, reading penumbra's EXR as an image, to `out`.
constexpr const char* kMatteScript = R"(import bpy, sys
path, layer, names, out, w, h = sys.argv[sys.argv.index("--") + 1:]
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y = int(w), int(h)
scene.render.resolution_percentage = 100
scene.render.engine = "BLENDER_WORKBENCH"
scene.use_nodes = True
tree = scene.node_tree
for n in list(tree.nodes):
    tree.nodes.remove(n)
crypto = tree.nodes.new("CompositorNodeCryptomatteV2")
crypto.source = "IMAGE"
crypto.image = bpy.data.images.load(path)
crypto.layer_name = layer
crypto.matte_id = names
composite = tree.nodes.new("CompositorNodeComposite")
tree.links.new(crypto.outputs["Matte"], composite.inputs["Image"])
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
)";

TEST(BlenderRoundTrip, CryptomatteMattesSelectTheirObjectsAndMaterials) {
    ASSERT_TRUE(std::filesystem::exists("/usr/bin/blender"))
        << "blender is not installed (Debian package blender; scripts/setup.sh --test)";
    const test::ScratchDir dir;
    const std::string exr = dir.file("crypto.exr");
    const test::CliResult r = test::run_penumbra(
        {"render", test::write_two_quads(dir), "-o", exr, "--width", "16", "--height", "16",
         "--spp", "4", "--filter", "box", "--aov", "cryptomatte", "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string script = dir.write("matte.py", kMatteScript);
    struct Case {
        const char* layer;
        const char* names;
        bool (*selected)(int, int);
    };
    const Case cases[] = {
        {"CryptoObject", "left", [](int x, int y) { return test::two_quads_left(x, y); }},
        {"CryptoObject", "right",
         [](int x, int y) { return !test::two_quads_miss(x, y) && !test::two_quads_left(x, y); }},
        {"CryptoMaterial", "default",
         [](int x, int y) { return !test::two_quads_miss(x, y) && !test::two_quads_left(x, y); }},
        {"CryptoObject", "left,right", [](int x, int y) { return !test::two_quads_miss(x, y); }},
    };
    for (const Case& c : cases) {
        const std::string out = dir.file(std::string("matte_") + c.names + ".exr");
        const std::string log =
            run_shell("/usr/bin/blender -b --factory-startup --python '" + script + "' -- '" + exr +
                      "' " + c.layer + " '" + c.names + "' '" + out + "' 16 16");
        const test::Pixels m = test::read_pixels(out);
        ASSERT_TRUE(m.error.empty()) << m.error << "\n" << log;
        ASSERT_EQ(m.width, 16) << log;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                EXPECT_EQ(m.data[(size_t(y) * 16 + x) * m.channels.size()],
                          c.selected(x, y) ? 1.0f : 0.0f)
                    << c.names << " at " << x << "," << y;
    }
}

}  // namespace
}  // namespace penumbra
