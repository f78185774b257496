// The AOV EXR round trip through Blender's compositor: Blender (Debian's blender, which
// scripts/setup.sh --test installs) opens penumbra's multi-channel EXR as a multilayer
// image whose compositor Image node offers every AOV as its own pass, under its name.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>
#include <string>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

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
    for (const char* p : {"Combined:RGBA", "Alpha:VALUE", "Albedo:RGBA", "Depth:VALUE",
                          "Normal:RGBA", "Position:RGBA", "Variance:RGBA", "Samples:VALUE",
                          "ObjectID:VALUE", "MaterialID:VALUE"})
        EXPECT_NE(passes.find(std::string(" ") + p + " "), std::string::npos)
            << p << " not among: " << passes;
}

}  // namespace
}  // namespace penumbra
