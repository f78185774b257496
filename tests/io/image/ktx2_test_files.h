// The KTX2 conformance files of ../shared/scenes/ktx2 (README there), read for the tests.
#pragma once

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/paths.h"

namespace penumbra::test {

inline std::string ktx2_path(const std::string& name) {
    return shared_path("scenes/ktx2/" + name + ".ktx2");
}

inline std::vector<uint8_t> read_ktx2(const std::string& name) {
    std::ifstream f(ktx2_path(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

}  // namespace penumbra::test
