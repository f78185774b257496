// A float's bit pattern, for tests that compare results bit for bit (so that -0 and +0,
// or two NaNs, differ).
#pragma once

#include <cstdint>
#include <cstring>

namespace penumbra::test {

inline uint32_t bits_of(float v) {
    uint32_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

}  // namespace penumbra::test
