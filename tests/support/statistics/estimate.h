// Monte Carlo estimates with their standard error, for t-tests of integrators against
// known answers (Nori's ttest, pbrt-v4's integrators_test).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

namespace penumbra::test {

struct Estimate {
    double mean = 0;
    double std_error = 0;  // standard deviation of the mean
    uint64_t count = 0;
};

// Mean of n evaluations of sample(i); Welford's running variance.
inline Estimate estimate(uint64_t n, const std::function<double(uint64_t)>& sample) {
    double mean = 0, m2 = 0;
    for (uint64_t i = 0; i < n; ++i) {
        const double x = sample(i);
        const double d = x - mean;
        mean += d / double(i + 1);
        m2 += d * (x - mean);
    }
    Estimate e;
    e.mean = mean;
    e.count = n;
    e.std_error = n > 1 ? std::sqrt(m2 / double(n - 1) / double(n)) : 0;
    return e;
}

// True when `expected` lies within z standard errors of the estimate. Zero-variance
// estimators (e.g. cosine sampling of a Lambertian under a uniform sky) are compared up
// to float rounding.
inline bool within(const Estimate& e, double expected, double z = 4.0) {
    return std::abs(e.mean - expected) <= std::max(z * e.std_error, 1e-6 * std::abs(expected));
}

}  // namespace penumbra::test
