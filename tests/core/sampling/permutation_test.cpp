#include "core/sampling/permutation.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "core/sampling/rng.h"

namespace penumbra {
namespace {

// Kensler 2013's permute() as published (with divisions and the mask built per call),
// with the wrap-safe last step: HashedPermutation must give the same values.
uint32_t kensler_permute(uint32_t i, uint32_t l, uint32_t p) {
    uint32_t w = l - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= p;
        i *= 0xe170893d;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3f;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1 | p >> 27;
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
    return (i + p % l) % l;
}

const uint32_t kKeys[] = {0u, 1u, 7u, 12345u, 0xdeadbeefu, 0xfffffff0u, 0xffffffffu};

TEST(FixedDivisor, ExactForEveryNumerator) {
    Rng rng(5);
    std::vector<uint32_t> divisors;
    for (uint32_t d = 1; d <= 300; ++d) divisors.push_back(d);
    for (uint32_t d : {1023u, 1024u, 65537u, 0x7fffffffu, 0x80000000u, 0xfffffffbu, 0xffffffffu})
        divisors.push_back(d);
    for (uint32_t d : divisors) {
        const FixedDivisor f(d);
        std::vector<uint32_t> a = {0u, 1u, d - 1, d, d + 1, 2 * d - 1, 0xfffffffeu, 0xffffffffu};
        for (int k = 0; k < 200; ++k) a.push_back(rng.next_u32());
        for (uint32_t v : a) {
            ASSERT_EQ(f.div(v), v / d) << v << " / " << d;
            ASSERT_EQ(f.mod(v), v % d) << v << " % " << d;
        }
    }
}

TEST(HashedPermutation, IsABijectionForEveryCount) {
    std::vector<uint32_t> counts;
    for (uint32_t n = 1; n <= 300; ++n) counts.push_back(n);
    for (uint32_t n : {511u, 512u, 513u, 1000u, 1023u, 1024u, 1025u, 4096u}) counts.push_back(n);
    for (uint32_t n : counts) {
        const HashedPermutation perm(n);
        ASSERT_EQ(perm.size(), n);
        // Keys near 2^32 once made the final offset wrap around.
        for (uint32_t key : kKeys) {
            std::vector<int> hits(n, 0);
            for (uint32_t i = 0; i < n; ++i) {
                const uint32_t e = perm(i, key);
                ASSERT_LT(e, n) << "n " << n << " key " << key;
                ++hits[e];
            }
            for (uint32_t e = 0; e < n; ++e)
                ASSERT_EQ(hits[e], 1) << "n " << n << " key " << key << " element " << e;
        }
    }
}

TEST(HashedPermutation, MatchesKenslersPermute) {
    // The samplers' values (and so every image) stay those of the published function.
    Rng rng(9);
    for (uint32_t n = 1; n <= 300; ++n) {
        const HashedPermutation perm(n);
        for (int k = 0; k < 8; ++k) {
            const uint32_t key = k < 7 ? kKeys[k] : rng.next_u32();
            for (uint32_t i = 0; i < n; ++i)
                ASSERT_EQ(perm(i, key), kensler_permute(i, n, key)) << n << " " << key << " " << i;
        }
    }
    for (uint32_t n : {1000u, 4096u, 65535u})
        for (int k = 0; k < 100; ++k) {
            const uint32_t key = rng.next_u32(), i = rng.next_below(n);
            ASSERT_EQ(permutation_element(i, n, key), kensler_permute(i, n, key));
        }
}

TEST(HashedPermutation, KeysSelectDifferentPermutations) {
    const uint32_t n = 12;
    std::set<std::vector<uint32_t>> seen;
    for (uint32_t key = 0; key < 16; ++key) {
        std::vector<uint32_t> perm;
        for (uint32_t i = 0; i < n; ++i)
            perm.push_back(permutation_element(i, n, key * 0x9e3779b9u));
        seen.insert(perm);
    }
    // 12! permutations: 16 keys colliding more than once would be a broken hash.
    EXPECT_GE(seen.size(), 15u);
}

}  // namespace
}  // namespace penumbra
