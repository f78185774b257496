#include "core/sampling/permutation.h"

namespace penumbra {

HashedPermutation::HashedPermutation(uint32_t n) : m_n(n) {
    uint32_t w = n - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    m_mask = w;
}

// Kensler's last step is (i + p) % l, which wraps at 2^32 when p > 2^32 - l and is then
// no permutation: (i + p % l) % l is, and the operator computes it without a division.
uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t key) {
    return HashedPermutation(n)(i, key);
}

}  // namespace penumbra
