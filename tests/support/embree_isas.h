// Embree's code paths in tests: which instruction sets this CPU runs, and a scope in which
// child processes (the penumbra binary) use one of them through PENUMBRA_EMBREE_CONFIG.
#pragma once

#include <string>
#include <vector>

namespace penumbra::test {

// "sse4.2", "avx2", "avx512": those of Embree 3's kernels this CPU can run (Embree's
// AVX-512 kernels need F, CD, DQ, BW and VL; its AVX2 ones FMA, BMI1/2 and LZCNT).
std::vector<std::string> embree_isas();

// Sets PENUMBRA_EMBREE_CONFIG=isa=<isa> until destroyed; an empty isa unsets it.
class ScopedEmbreeIsa {
public:
    explicit ScopedEmbreeIsa(const std::string& isa);
    ~ScopedEmbreeIsa();
    ScopedEmbreeIsa(const ScopedEmbreeIsa&) = delete;
    ScopedEmbreeIsa& operator=(const ScopedEmbreeIsa&) = delete;

private:
    bool m_had = false;
    std::string m_old;
};

}  // namespace penumbra::test
