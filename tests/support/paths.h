// Where tests find the repository's scenes, the shared Khronos samples and the build.
#pragma once

#include <string>

namespace penumbra::test {

inline std::string source_path(const std::string& rel) {
    return std::string(PENUMBRA_SOURCE_DIR) + "/" + rel;
}
inline std::string shared_path(const std::string& rel) {
    return std::string(PENUMBRA_SHARED_DIR) + "/" + rel;
}
inline std::string binary_path(const std::string& rel) {
    return std::string(PENUMBRA_BINARY_DIR) + "/" + rel;
}

}  // namespace penumbra::test
