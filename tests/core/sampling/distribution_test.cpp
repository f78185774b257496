// Distribution1D's guide table must find exactly the bin that a binary search over the
// CDF finds (the environment light's samples stayed bit for bit the same when it came).
#include "core/sampling/distribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/sampling/rng.h"

namespace penumbra {
namespace {

// The CDF as the constructor builds it, and the sample without the guide table:
// upper_bound over the whole CDF.
struct Reference {
    std::vector<float> func, cdf;
    float integral = 0;
    explicit Reference(std::vector<float> f) : func(std::move(f)) {
        const size_t n = func.size();
        for (float& v : func) v = (v > 0 && std::isfinite(v)) ? v : 0.0f;
        cdf.assign(n + 1, 0);
        double acc = 0;
        for (size_t i = 0; i < n; ++i) {
            acc += double(func[i]) / n;
            cdf[i + 1] = static_cast<float>(acc);
        }
        integral = static_cast<float>(acc);
        if (!(acc > 0)) {
            for (size_t i = 0; i <= n; ++i) cdf[i] = float(i) / n;
            std::fill(func.begin(), func.end(), 1.0f);
            integral = 1;
        } else {
            for (size_t i = 1; i <= n; ++i) cdf[i] = static_cast<float>(cdf[i] / acc);
        }
        cdf[n] = 1;
    }
    float sample(float u, float* pdf, int* offset) const {
        const size_t n = func.size();
        size_t i = std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin();
        i = std::clamp<size_t>(i, 1, n) - 1;
        while (i + 1 < n && func[i] == 0) ++i;
        *offset = static_cast<int>(i);
        float du = u - cdf[i];
        const float width = cdf[i + 1] - cdf[i];
        if (width > 0) du /= width;
        *pdf = func[i] / integral;
        return std::min((i + std::clamp(du, 0.0f, 1.0f)) / n, 0x1.fffffep-1f);
    }
};

// Functions with zero runs, a sun-like spike, ramps and sizes around powers of two.
std::vector<std::vector<float>> functions() {
    std::vector<std::vector<float>> fs;
    for (const size_t n : {1u, 2u, 3u, 7u, 8u, 9u, 100u, 256u, 1000u}) {
        std::vector<float> ramp(n), spike(n, 0.01f), sparse(n, 0.0f), zeros(n, 0.0f);
        for (size_t i = 0; i < n; ++i) ramp[i] = float(i % 17);
        spike[n / 2] = 1e5f;
        for (size_t i = 0; i < n; i += 5) sparse[i] = float(1 + i % 3);
        fs.push_back(ramp);
        fs.push_back(spike);
        fs.push_back(sparse);
        fs.push_back(zeros);
    }
    return fs;
}

TEST(Distribution1D, GuideTableFindsTheBinarySearchsBin) {
    Rng rng(7);
    for (const std::vector<float>& f : functions()) {
        const Distribution1D d(f);
        const Reference ref(f);
        // Random u, every CDF entry and its float neighbours (the search's edge cases),
        // and the ends of [0, 1).
        std::vector<float> us = {0.0f, 0x1.fffffep-1f, 1e-30f, 0.5f};
        for (int k = 0; k < 2000; ++k) us.push_back(rng.next_float());
        for (const float c : ref.cdf)
            for (const float u : {std::nextafter(c, -1.0f), c, std::nextafter(c, 2.0f)})
                if (u >= 0 && u < 1) us.push_back(u);
        for (const float u : us) {
            float pdf, pdf_ref;
            int offset, offset_ref;
            const float x = d.sample_continuous(u, &pdf, &offset);
            const float x_ref = ref.sample(u, &pdf_ref, &offset_ref);
            ASSERT_EQ(offset, offset_ref) << "n " << f.size() << " u " << u;
            ASSERT_EQ(x, x_ref) << "n " << f.size() << " u " << u;
            ASSERT_EQ(pdf, pdf_ref) << "n " << f.size() << " u " << u;
            // pdf(x) as it divided per call (x may sit on the next bin's lower edge).
            const size_t bin = std::min(static_cast<size_t>(x * f.size()), f.size() - 1);
            ASSERT_EQ(d.pdf(x), ref.func[bin] / ref.integral) << "n " << f.size() << " u " << u;
        }
    }
}

}  // namespace
}  // namespace penumbra
