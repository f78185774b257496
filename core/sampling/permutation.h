// Pseudo-random permutations of [0, n) selected by a key, evaluated one element at a time
// (Kensler 2013, "Correlated Multi-Jittered Sampling", the cycle-walking hash), with what
// depends on n alone (the mask, the reductions mod n) set up once per sampler.
#pragma once

#include <cstdint>

namespace penumbra {

// Division and remainder by a fixed 32-bit divisor through one 64 x 64-bit multiply
// (Lemire, Kaser & Kurz 2019, "Faster remainder by direct computation", fastmod and
// fastdiv with a 64-bit M = floor(2^64 / d) + 1: exact for every 32-bit numerator).
class FixedDivisor {
public:
    explicit FixedDivisor(uint32_t d = 1) : m_d(d), m_m(d > 1 ? ~0ull / d + 1 : 0) {}
    uint32_t divisor() const { return m_d; }
    uint32_t div(uint32_t a) const {
        // d = 1 has no 64-bit M (2^64 wraps to 0); there a / d is a itself.
        return m_d > 1 ? uint32_t((static_cast<unsigned __int128>(m_m) * a) >> 64) : a;
    }
    uint32_t mod(uint32_t a) const {
        const uint64_t low = m_m * a;  // the fraction a / d, scaled by 2^64
        return uint32_t((static_cast<unsigned __int128>(low) * m_d) >> 64);
    }

private:
    uint32_t m_d;
    uint64_t m_m;
};

class HashedPermutation {
public:
    explicit HashedPermutation(uint32_t n = 1);
    uint32_t size() const { return m_n.divisor(); }
    // Element i (< size()) of the permutation selected by key. Equals Kensler's
    // permute(i, n, key) except for the last step, which wraps exactly (see the .cpp).
    uint32_t operator()(uint32_t i, uint32_t key) const {
        const uint32_t l = m_n.divisor(), w = m_mask;
        // Cycle walking: the hash permutes [0, w + 1), the smallest power of two >= l;
        // values outside [0, l) are hashed again until one falls inside (at most two
        // rounds expected; exactly one when l is a power of two).
        do {
            i ^= key;
            i *= 0xe170893d;
            i ^= key >> 16;
            i ^= (i & w) >> 4;
            i ^= key >> 8;
            i *= 0x0929eb3f;
            i ^= key >> 23;
            i ^= (i & w) >> 1;
            i *= 1 | key >> 27;
            i *= 0x6935fa69;
            i ^= (i & w) >> 11;
            i *= 0x74dcb303;
            i ^= (i & w) >> 2;
            i *= 0x9e501cc3;
            i ^= (i & w) >> 2;
            i *= 0xc860a3df;
            i &= w;
            i ^= i >> 5;
        } while (i >= l);
        // (i + key mod l) mod l: both terms are below l, so one subtraction reduces it.
        const uint32_t r = i + m_n.mod(key);
        return r >= l ? r - l : r;
    }

private:
    FixedDivisor m_n;
    uint32_t m_mask;  // the smallest 2^k - 1 >= n - 1
};

// Element i of the permutation of [0, n) selected by key: HashedPermutation(n)(i, key),
// setting up n on every call (for one-off use; samplers keep a HashedPermutation).
uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t key);

}  // namespace penumbra
