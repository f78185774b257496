#include "io/gltf/gltf_signature.h"

#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/error.h"

namespace penumbra {

namespace {

bool json_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// The first word of the text, up to 16 characters, bytes outside printable ASCII as \xNN,
// so that a binary file prints as one short line.
std::string first_word(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size() && i < 16 && !json_space(text[i]); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f && c != '\'') {
            out += char(c);
        } else {
            char hex[5];
            std::snprintf(hex, sizeof(hex), "\\x%02X", c);
            out += hex;
        }
    }
    return out;
}

}  // namespace

void check_gltf_signature(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    // Leading whitespace of any length is valid JSON; 4 KiB is plenty for real files.
    std::string head(4096, '\0');
    file.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(file.gcount()));
    if (head.compare(0, 4, "glTF") == 0) return;  // GLB (glTF 2.0, section 4.4.2)
    size_t i = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (i < head.size() && json_space(head[i])) ++i;
    if (i < head.size() && head[i] == '{') return;
    if (head.empty()) throw SceneError(path + ": not a glTF file: it is empty");
    if (i == head.size() && head.size() < 4096)
        throw SceneError(path + ": not a glTF file: it holds only whitespace");
    if (i == head.size()) return;  // more whitespace than we read: let the parser decide
    throw SceneError(path + ": not a glTF file: begins with '" + first_word(head.substr(i)) + "'");
}

}  // namespace penumbra
