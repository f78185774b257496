// Files that are not glTF are named as such before tinygltf parses them: an HTML page or
// an image saved as .glb or .gltf, an empty file; JSON with a byte order mark or leading
// whitespace still loads.
#include "io/gltf/gltf_signature.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::ScratchDir;

std::string load_error(const std::string& path) {
    try {
        load_gltf(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(GltfSignature, NotGltfFilesSaySo) {
    ScratchDir dir;
    const std::pair<std::string, std::string> cases[] = {
        {"<!DOCTYPE html>\n<html><body>Not found</body></html>", "begins with '<!DOCTYPE'"},
        {"  \r\n<html lang=en>", "begins with '<html'"},
        {std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), "begins with '\\x89PNG'"},
        {"GIF89a", "begins with 'GIF89a'"},
        {"[1, 2, 3]", "begins with '[1,'"},
        {"it's a very long first word of text", "begins with 'it\\x27s'"},
        {"abcdefghijklmnopqrstuvwxyz", "begins with 'abcdefghijklmnop'"},
        {"", "it is empty"},
        {" \n\t ", "it holds only whitespace"},
    };
    for (const auto& [text, why] : cases) {
        for (const char* name : {"page.glb", "page.gltf"}) {
            const std::string path = dir.write(name, text);
            EXPECT_EQ(load_error(path), path + ": not a glTF file: " + why);
        }
    }
}

TEST(GltfSignature, GlbMagicAndJsonObjectsPass) {
    ScratchDir dir;
    const std::string scene = R"({"asset": {"version": "2.0"}})";
    for (const std::string& text : {scene, "\xEF\xBB\xBF" + scene, " \r\n\t" + scene}) {
        const std::string path = dir.write("ok.gltf", text);
        EXPECT_NO_THROW(check_gltf_signature(path));
    }
    EXPECT_NO_THROW(check_gltf_signature(dir.write("a.glb", "glTF\x02")));
    // Broken JSON that starts like an object is left to the parser and its message.
    const std::string broken = dir.write("broken.gltf", "{\"asset\": ");
    const std::string error = load_error(broken);
    EXPECT_EQ(error.rfind(broken + ": ", 0), 0u) << error;
    EXPECT_EQ(error.find("not a glTF file"), std::string::npos) << error;
}

}  // namespace
}  // namespace penumbra
