// Integer hashing for seeding: a pixel's random numbers are a pure function of
// (seed, pixel, sample index, dimension), which makes renders bitwise reproducible
// whatever the thread count or tile order.
#pragma once

#include <cstdint>

namespace penumbra {

// SplitMix64 finalizer (Steele et al. 2014): a strong 64-bit mixing function.
inline uint64_t mix_bits(uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ULL;
    v ^= v >> 27;
    v *= 0x81dadef4bc2dd44dULL;
    v ^= v >> 33;
    return v;
}

inline uint64_t hash_combine(uint64_t seed, uint64_t v) {
    return mix_bits(seed ^ (v + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2)));
}

template <typename... Args>
uint64_t hash_values(uint64_t first, Args... rest) {
    uint64_t h = mix_bits(first + 0x9e3779b97f4a7c15ULL);
    ((h = hash_combine(h, static_cast<uint64_t>(rest))), ...);
    return h;
}

}  // namespace penumbra
