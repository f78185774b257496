#include "core/film/film.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/convergence.h"

namespace penumbra {

Film::Film(int width, int height, AovSet aovs)
    : m_width(width), m_height(height), m_pixels(size_t(width) * height), m_aovs(aovs) {
    const size_t n = m_pixels.size();
    if (aovs.has(Aov::Albedo)) m_aov.albedo.assign(n, Sum3{});
    if (aovs.has(Aov::Normal)) m_aov.normal.assign(n, Sum3{});
    if (aovs.has(Aov::Albedo) || aovs.has(Aov::Normal)) m_aov.weight.assign(n, 0.0);
    if (aovs.has(Aov::Depth)) m_aov.depth.assign(n, 0.0);
    if (aovs.has(Aov::Position)) m_aov.position.assign(n, Sum3{});
    if (aovs.has(Aov::Depth) || aovs.has(Aov::Position)) m_aov.hit_weight.assign(n, 0.0);
    if (aovs.has(Aov::Variance)) {
        m_aov.square.assign(n, Sum3{});
        m_aov.weight2.assign(n, 0.0);
    }
    if (aovs.has(Aov::Samples)) m_aov.count.assign(n, 0);
    if (aovs.has(Aov::Error)) {
        m_aov.odd.assign(n, Sum3{});
        m_aov.odd_weight.assign(n, 0.0);
    }
}

void Film::add_sample(int x, int y, Spectrum L, float w) {
    Pixel& px = m_pixels[size_t(y) * m_width + x];
    if (!is_finite(L)) {
        // A NaN or Inf would poison the pixel forever; drop it and keep count.
        ++px.nonfinite;
        return;
    }
    px.sum[0] += double(L.x) * w;
    px.sum[1] += double(L.y) * w;
    px.sum[2] += double(L.z) * w;
    px.weight += w;
}

void Film::add_sample(int x, int y, Spectrum L, float w, const AovRecord& aov) {
    const size_t i = size_t(y) * m_width + x;
    add_sample(x, y, L, w);
    auto add3 = [](std::vector<Sum3>& v, size_t k, Vec3 a, double w) {
        if (v.empty()) return;
        for (int c = 0; c < 3; ++c) v[k][c] += double(a[c]) * w;
    };
    if (!m_aov.count.empty()) ++m_aov.count[i];
    if (!m_aov.square.empty() && is_finite(L)) {
        add3(m_aov.square, i, L * L, w);
        m_aov.weight2[i] += double(w) * w;
    }
    if (aov.odd && !m_aov.odd.empty() && is_finite(L)) {
        add3(m_aov.odd, i, L, w);
        m_aov.odd_weight[i] += w;
    }
    if (!m_aov.weight.empty()) {
        m_aov.weight[i] += w;
        if (aov.hit) {
            add3(m_aov.albedo, i, aov.albedo, w);
            add3(m_aov.normal, i, aov.normal, w);
        }
    }
    if (!m_aov.hit_weight.empty() && aov.hit) {
        m_aov.hit_weight[i] += w;
        if (!m_aov.depth.empty()) m_aov.depth[i] += double(aov.depth) * w;
        add3(m_aov.position, i, aov.position, w);
    }
}

Spectrum Film::estimated_variance(int x, int y) const {
    if (m_aov.odd.empty()) return Spectrum(0);
    const size_t i = size_t(y) * m_width + x;
    const Pixel& px = m_pixels[i];
    const double nb = m_aov.odd_weight[i], na = px.weight - nb;
    // Rounding can leave a sliver of weight in an empty half; 1e-9 of the total is none.
    if (!(na > 1e-9 * px.weight && nb > 1e-9 * px.weight)) return Spectrum(0);
    const double k = na * nb / (px.weight * px.weight);
    Spectrum v;
    for (int c = 0; c < 3; ++c) {
        const double b = m_aov.odd[i][c] / nb, a = (px.sum[c] - m_aov.odd[i][c]) / na;
        v[c] = float((a - b) * (a - b) * k);
    }
    return v;
}

float Film::relative_error(int x, int y) const {
    const Pixel& px = m_pixels[size_t(y) * m_width + x];
    if (px.weight == 0) return std::numeric_limits<float>::infinity();
    const Spectrum v = estimated_variance(x, y);
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
        const double mean = px.sum[c] / px.weight;
        sum += v[c] / (mean * mean + kRelMseEpsilon);
    }
    return float(std::sqrt(sum / 3));
}

Image Film::resolve_aov(Aov aov) const {
    const bool scalar = aov == Aov::Depth || aov == Aov::Samples || aov == Aov::Error;
    Image img(m_width, m_height, scalar ? 1 : 3);
    if (!m_aovs.has(aov)) return img;
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        float* out = &img.pixels[i * img.channels];
        auto mean3 = [&](const std::vector<Sum3>& v, double weight) {
            const double inv = weight != 0 ? 1.0 / weight : 0.0;
            for (int c = 0; c < 3; ++c) out[c] = float(v[i][c] * inv);
        };
        switch (aov) {
            case Aov::Albedo:
                mean3(m_aov.albedo, m_aov.weight[i]);
                break;
            case Aov::Normal:
                mean3(m_aov.normal, m_aov.weight[i]);
                break;
            case Aov::Position:
                mean3(m_aov.position, m_aov.hit_weight[i]);
                break;
            case Aov::Depth:
                out[0] = m_aov.hit_weight[i] != 0 ? float(m_aov.depth[i] / m_aov.hit_weight[i])
                                                  : kNoHitDepth;
                break;
            case Aov::Samples:
                out[0] = float(m_aov.count[i]);
                break;
            case Aov::Error:
                out[0] = relative_error(int(i % m_width), int(i / m_width));
                break;
            case Aov::Variance: {
                // Weighted variance over the effective sample count, less one: for equal
                // weights exactly the unbiased s^2 / n (a ratio estimator's variance).
                const Pixel& px = m_pixels[i];
                const double sw = px.weight, sw2 = m_aov.weight2[i];
                const double n_eff = sw2 > 0 ? sw * sw / sw2 : 0;
                for (int c = 0; c < 3; ++c) {
                    if (!(n_eff > 1.0 + 1e-9)) {
                        out[c] = 0;
                        continue;
                    }
                    const double mean = px.sum[c] / sw;
                    const double var = std::max(0.0, m_aov.square[i][c] / sw - mean * mean);
                    out[c] = float(var / (n_eff - 1));
                }
                break;
            }
        }
    }
    return img;
}

Image Film::resolve() const {
    Image img(m_width, m_height, 4);
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x) {
            const Pixel& px = m_pixels[size_t(y) * m_width + x];
            float* out = img.at(x, y);
            const double inv = px.weight != 0 ? 1.0 / px.weight : 0.0;
            for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(px.sum[c] * inv);
            out[3] = 1;
        }
    return img;
}

std::vector<Film::Buffer> Film::buffers() {
    auto raw = [](const char* name, auto& v) {
        return Buffer{name, v.data(), v.size() * sizeof(v[0])};
    };
    // Empty AOV buffers are listed too (0 bytes): the list is the same for every film.
    return {raw("pixels", m_pixels),         raw("albedo", m_aov.albedo),
            raw("normal", m_aov.normal),     raw("position", m_aov.position),
            raw("square", m_aov.square),     raw("weight", m_aov.weight),
            raw("hit_weight", m_aov.hit_weight), raw("depth", m_aov.depth),
            raw("weight2", m_aov.weight2),   raw("count", m_aov.count),
            raw("odd", m_aov.odd),           raw("odd_weight", m_aov.odd_weight)};
}

uint64_t Film::nonfinite_samples() const {
    uint64_t n = 0;
    for (const Pixel& px : m_pixels) n += px.nonfinite;
    return n;
}

}  // namespace penumbra
