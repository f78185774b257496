// Checks shared by the pixel samplers' tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <memory>

#include "core/sampling/sampler.h"
#include "tests/support/statistics/estimate.h"

namespace penumbra::test {

// A render stopped early uses a prefix of each pixel's budget (RenderOptions::spp): the
// first 1, 5 and 64 of 64 samples must each be unbiased. make(seed) builds a sampler for
// 64 spp; independent replicates are the seeds (within one, pixels may share one
// scrambled sequence, so they are not independent samples). The integrand is a corner
// of [0,1)^2 per pair, off the dyadic grid so stratification alone cannot make it exact:
// the mean of 1[x < 0.3] 1[y < 0.7] is 0.21.
inline void expect_unbiased_prefixes(
    const std::function<std::unique_ptr<Sampler>(uint64_t seed)>& make) {
    for (uint32_t prefix : {1u, 5u, 64u}) {
        const Estimate e = estimate(200, [&](uint64_t seed) {
            const std::unique_ptr<Sampler> s = make(1000 + seed);
            double sum = 0;
            int count = 0;
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x)
                    for (uint32_t i = 0; i < prefix; ++i) {
                        s->start_pixel_sample({x, y}, i);
                        for (int d = 0; d < 3; ++d) {
                            const Vec2 v = s->get_2d();
                            sum += (v.x < 0.3f) * (v.y < 0.7f);
                            ++count;
                        }
                    }
            return sum / count;
        });
        EXPECT_TRUE(within(e, 0.21))
            << "prefix " << prefix << ": " << e.mean << " +- " << e.std_error;
        // Power: a bias of 0.005 (2.4%) would be four standard errors.
        EXPECT_LT(e.std_error, 0.00125) << "prefix " << prefix;
    }
}

}  // namespace penumbra::test
