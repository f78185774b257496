// PCG32 (O'Neill 2014): small state, good statistical quality, and independent streams
// selected by the increment.
#pragma once

#include <cstdint>

namespace penumbra {

class Rng {
public:
    Rng() { seed(0x853c49e6748fea9bULL, 0xda3e39cb94b95bdbULL); }
    Rng(uint64_t state, uint64_t stream = 0xda3e39cb94b95bdbULL) { seed(state, stream); }

    void seed(uint64_t state, uint64_t stream) {
        m_state = 0;
        m_inc = (stream << 1u) | 1u;
        next_u32();
        m_state += state;
        next_u32();
    }
    uint32_t next_u32() {
        const uint64_t old = m_state;
        m_state = old * 0x5851f42d4c957f2dULL + m_inc;
        const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
    }
    // Uniform in [0, 1): 24 random mantissa bits, so the result is never rounded to 1.
    float next_float() { return (next_u32() >> 8) * 0x1p-24f; }
    // Uniform integer in [0, n) without modulo bias (Lemire's rejection).
    uint32_t next_below(uint32_t n) {
        const uint32_t threshold = (~n + 1u) % n;
        for (;;) {
            const uint32_t r = next_u32();
            if (r >= threshold) return r % n;
        }
    }

private:
    uint64_t m_state = 0, m_inc = 1;
};

}  // namespace penumbra
