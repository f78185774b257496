#include "support/embree_isas.h"

#include <cstdlib>

namespace penumbra::test {

std::vector<std::string> embree_isas() {
    std::vector<std::string> isas;
    __builtin_cpu_init();
    if (__builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt"))
        isas.push_back("sse4.2");
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
        __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2"))
        isas.push_back("avx2");
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
        __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512vl"))
        isas.push_back("avx512");
    return isas;
}

ScopedEmbreeIsa::ScopedEmbreeIsa(const std::string& isa) {
    if (const char* old = std::getenv("PENUMBRA_EMBREE_CONFIG")) {
        m_had = true;
        m_old = old;
    }
    if (isa.empty())
        unsetenv("PENUMBRA_EMBREE_CONFIG");
    else
        setenv("PENUMBRA_EMBREE_CONFIG", ("isa=" + isa).c_str(), 1);
}

ScopedEmbreeIsa::~ScopedEmbreeIsa() {
    if (m_had)
        setenv("PENUMBRA_EMBREE_CONFIG", m_old.c_str(), 1);
    else
        unsetenv("PENUMBRA_EMBREE_CONFIG");
}

}  // namespace penumbra::test
