#include "core/film/film.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/film/image_error.h"
#include "core/error.h"

namespace penumbra {

namespace {

// A sample's guide record as denoise_input.h's channels.
std::array<float, kGuideChannels> guide_channels(const GuideRecord& g) {
    static_assert(kGuideAlbedo == 0 && kGuideNormal == 3 && kGuideDepth == 6 &&
                  kGuideVisibility == 7);
    return {g.albedo.x, g.albedo.y, g.albedo.z, g.normal.x,
            g.normal.y, g.normal.z, g.depth,    g.visibility};
}

// The variance of a weighted mean from its sums (sum w x, sum w x^2, sum w, sum w^2): the
// weighted variance over the effective sample count (sum w)^2 / sum w^2, less one. For
// equal weights exactly the unbiased s^2 / n (a ratio estimator's variance); 0 below two
// samples.
double variance_of_mean(double sum, double square, double sw, double sw2) {
    const double n_eff = sw2 > 0 ? sw * sw / sw2 : 0;
    if (!(n_eff > 1.0 + 1e-9)) return 0;
    const double mean = sum / sw;
    const double var = std::max(0.0, square / sw - mean * mean);
    return var / (n_eff - 1);
}

}  // namespace

Film::Film(int width, int height, AovSet aovs)
    : m_width(width), m_height(height), m_pixels(size_t(width) * height), m_aovs(aovs) {
    const size_t n = m_pixels.size();
    if (aovs.has(Aov::Albedo)) m_aov.albedo.assign(n, Sum3{});
    if (aovs.has(Aov::Normal)) m_aov.normal.assign(n, Sum3{});
    if (aovs.has(Aov::Albedo) || aovs.has(Aov::Normal)) m_aov.weight.assign(n, 0.0);
    if (aovs.has(Aov::Depth)) m_aov.depth.assign(n, 0.0);
    if (aovs.has(Aov::Position)) m_aov.position.assign(n, Sum3{});
    if (aovs.has(Aov::Vector)) m_aov.motion.assign(n, std::array<double, 4>{});
    if (aovs.has(Aov::Depth) || aovs.has(Aov::Position) || aovs.has(Aov::Vector))
        m_aov.hit_weight.assign(n, 0.0);
    const bool denoise = aovs.has(Aov::Denoise);
    if (aovs.has(Aov::Variance) || denoise) {
        m_aov.square.assign(n, Sum3{});
        m_aov.weight2.assign(n, 0.0);
    }
    if (aovs.has(Aov::Samples)) m_aov.count.assign(n, 0);
    if (aovs.splits_halves()) {
        m_aov.odd.assign(n, Sum3{});
        m_aov.odd_weight.assign(n, 0.0);
    }
    if (aovs.has(Aov::Coverage)) m_aov.coverage.assign(n, 0.0);
    if (aovs.has(Aov::Coverage) && aovs.splits_halves()) m_aov.coverage_odd.assign(n, 0.0);
    if (aovs.has_ids()) m_aov.ids.assign(n, IdSample{});
    if (aovs.has(Aov::CryptoObject)) m_aov.crypto_object.assign(n, CryptomatteSlots{});
    if (aovs.has(Aov::CryptoMaterial)) m_aov.crypto_material.assign(n, CryptomatteSlots{});
    if (denoise) {
        m_aov.guide.assign(n, Guide{});
        m_aov.guide_odd.assign(n, Guide{});
        m_aov.guide_square.assign(n, Guide{});
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
    // Alpha is filtered as the colour is: a sample the colour drops is no coverage either.
    if (!m_aov.coverage.empty() && is_finite(L)) {
        m_aov.coverage[i] += double(aov.coverage) * w;
        if (aov.odd && !m_aov.coverage_odd.empty())
            m_aov.coverage_odd[i] += double(aov.coverage) * w;
    }
    // Coverage in the colour's weights: a sample the colour drops counts for no ID.
    if (aov.hit && is_finite(L)) {
        if (!m_aov.crypto_object.empty()) m_aov.crypto_object[i].add(aov.object_hash, w);
        if (!m_aov.crypto_material.empty()) m_aov.crypto_material[i].add(aov.material_hash, w);
    }
    // Strictly nearer only: of equally near samples the first (in index order) stays.
    if (!m_aov.ids.empty() && aov.offset2 < m_aov.ids[i].offset2)
        m_aov.ids[i] = {aov.offset2, aov.object, aov.material};
    if (!m_aov.square.empty() && is_finite(L)) {
        add3(m_aov.square, i, L * L, w);
        m_aov.weight2[i] += double(w) * w;
    }
    if (aov.odd && !m_aov.odd.empty() && is_finite(L)) {
        add3(m_aov.odd, i, L, w);
        m_aov.odd_weight[i] += w;
    }
    // A sample the beauty drops leaves the guides too, so that their halves have the
    // colour's weights.
    if (!m_aov.guide.empty() && is_finite(L)) {
        const std::array<float, kGuideChannels> g = guide_channels(aov.guide);
        for (int c = 0; c < kGuideChannels; ++c) {
            const double wg = double(g[c]) * w;
            m_aov.guide[i][c] += wg;
            m_aov.guide_square[i][c] += wg * g[c];
            if (aov.odd) m_aov.guide_odd[i][c] += wg;
        }
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
        // Weighted like depth, over the samples that hit: Cycles, too, sums each sample's
        // vector with a weight of its own and divides by that weight's sum.
        if (!m_aov.motion.empty())
            for (int c = 0; c < 4; ++c) m_aov.motion[i][size_t(c)] += double(aov.motion[c]) * w;
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
    const size_t i = size_t(y) * m_width + x;
    const Pixel& px = m_pixels[i];
    if (px.weight == 0) return std::numeric_limits<float>::infinity();
    const Spectrum v = estimated_variance(x, y);
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
        const double mean = px.sum[c] / px.weight;
        sum += v[c] / (mean * mean + kRelMseEpsilon);
    }
    if (m_aov.coverage_odd.empty()) return float(std::sqrt(sum / 3));
    // A transparent background's alpha is an estimate too: a dark object's edge, whose
    // colour is near 0 either way, must not stop while its alpha is still noisy.
    const double nb = m_aov.odd_weight[i], na = px.weight - nb;
    if (na > 1e-9 * px.weight && nb > 1e-9 * px.weight) {
        const double b = m_aov.coverage_odd[i] / nb,
                     a = (m_aov.coverage[i] - m_aov.coverage_odd[i]) / na;
        const double mean = m_aov.coverage[i] / px.weight;
        const double variance = (a - b) * (a - b) * na * nb / (px.weight * px.weight);
        sum += variance / (mean * mean + kRelMseEpsilon);
    }
    return float(std::sqrt(sum / 4));
}

Image Film::resolve_aov(Aov aov) const {
    const bool scalar = aov == Aov::Depth || aov == Aov::Samples || aov == Aov::Error ||
                        aov == Aov::ObjectId || aov == Aov::MaterialId;
    const bool crypto = aov == Aov::CryptoObject || aov == Aov::CryptoMaterial;
    Image img(m_width, m_height,
              crypto ? 2 * kCryptomatteRanks : scalar ? 1 : aov == Aov::Vector ? 4 : 3);
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
            case Aov::Vector:
                for (int c = 0; c < 4; ++c)
                    out[c] = m_aov.hit_weight[i] != 0
                                 ? float(m_aov.motion[i][size_t(c)] / m_aov.hit_weight[i])
                                 : 0.0f;
                break;
            case Aov::Samples:
                out[0] = float(m_aov.count[i]);
                break;
            case Aov::Error:
                out[0] = relative_error(int(i % m_width), int(i / m_width));
                break;
            case Aov::Variance:
                for (int c = 0; c < 3; ++c)
                    out[c] = float(variance_of_mean(m_pixels[i].sum[c], m_aov.square[i][c],
                                                    m_pixels[i].weight, m_aov.weight2[i]));
                break;
            case Aov::ObjectId:
                out[0] = float(m_aov.ids[i].object);
                break;
            case Aov::MaterialId:
                out[0] = float(m_aov.ids[i].material);
                break;
            case Aov::CryptoObject:
            case Aov::CryptoMaterial: {
                const CryptomatteSlots& slots = aov == Aov::CryptoObject ? m_aov.crypto_object[i]
                                                                         : m_aov.crypto_material[i];
                const auto ranked = slots.ranked(m_pixels[i].weight);
                for (int r = 0; r < kCryptomatteRanks; ++r) {
                    out[2 * r] = ranked[size_t(r)].first;
                    out[2 * r + 1] = ranked[size_t(r)].second;
                }
                break;
            }
            case Aov::Denoise:
            case Aov::Coverage:
                break;  // not images of their own: denoise_input(), resolve()'s alpha
        }
    }
    return img;
}

DenoiseInput Film::denoise_input() const {
    CHECK(m_aovs.has(Aov::Denoise), "the film was made without denoising buffers");
    DenoiseInput in;
    in.color_a = in.color_b = in.color_variance = Image(m_width, m_height, 3);
    in.guide_a = in.guide_b = in.guide_variance = Image(m_width, m_height, kGuideChannels);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        const Pixel& px = m_pixels[i];
        const double nb = m_aov.odd_weight[i], na = px.weight - nb;
        // As in estimated_variance: a sliver of rounding in an empty half is no weight.
        const bool has_a = na > 1e-9 * px.weight, has_b = nb > 1e-9 * px.weight;
        auto halves = [&](double sum, double odd, float* a, float* b) {
            *a = has_a ? float((sum - odd) / na) : 0.0f;
            *b = has_b ? float(odd / nb) : 0.0f;
        };
        for (int c = 0; c < 3; ++c) {
            const size_t k = i * 3 + size_t(c);
            halves(px.sum[c], m_aov.odd[i][c], &in.color_a.pixels[k], &in.color_b.pixels[k]);
            in.color_variance.pixels[k] =
                float(variance_of_mean(px.sum[c], m_aov.square[i][c], px.weight, m_aov.weight2[i]));
        }
        for (int c = 0; c < kGuideChannels; ++c) {
            const size_t k = i * kGuideChannels + size_t(c);
            halves(m_aov.guide[i][c], m_aov.guide_odd[i][c], &in.guide_a.pixels[k],
                   &in.guide_b.pixels[k]);
            in.guide_variance.pixels[k] = float(variance_of_mean(
                m_aov.guide[i][c], m_aov.guide_square[i][c], px.weight, m_aov.weight2[i]));
        }
    }
    return in;
}

Image Film::resolve() const {
    Image img(m_width, m_height, 4);
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x) {
            const Pixel& px = m_pixels[size_t(y) * m_width + x];
            float* out = img.at(x, y);
            const double inv = px.weight != 0 ? 1.0 / px.weight : 0.0;
            for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(px.sum[c] * inv);
            out[3] = m_aov.coverage.empty()
                         ? 1.0f
                         : static_cast<float>(m_aov.coverage[size_t(y) * m_width + x] * inv);
        }
    return img;
}

std::vector<Film::Buffer> Film::buffers() {
    auto raw = [](const char* name, auto& v) {
        return Buffer{name, v.data(), v.size() * sizeof(v[0])};
    };
    // Empty AOV buffers are listed too (0 bytes): the list is the same for every film.
    return {raw("pixels", m_pixels),
            raw("albedo", m_aov.albedo),
            raw("normal", m_aov.normal),
            raw("position", m_aov.position),
            raw("square", m_aov.square),
            raw("weight", m_aov.weight),
            raw("hit_weight", m_aov.hit_weight),
            raw("depth", m_aov.depth),
            raw("weight2", m_aov.weight2),
            raw("count", m_aov.count),
            raw("odd", m_aov.odd),
            raw("odd_weight", m_aov.odd_weight),
            raw("guide", m_aov.guide),
            raw("guide_odd", m_aov.guide_odd),
            raw("guide_square", m_aov.guide_square),
            raw("coverage", m_aov.coverage),
            raw("coverage_odd", m_aov.coverage_odd),
            raw("ids", m_aov.ids),
            raw("crypto_object", m_aov.crypto_object),
            raw("crypto_material", m_aov.crypto_material),
            raw("motion", m_aov.motion)};
}

uint64_t Film::nonfinite_samples() const {
    uint64_t n = 0;
    for (const Pixel& px : m_pixels) n += px.nonfinite;
    return n;
}

}  // namespace penumbra
