#include "core/denoise/nl_means.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace penumbra {

namespace {

// Keeps the distance's denominator from 0 where both variances are (a noise-free guide).
constexpr float kEpsilon = 1e-10f;

}  // namespace

void patch_weights(const NlmGuide& g, const float* ks, int nk, int x0, int y0, int x1, int y1,
                   int dx, int dy, float* const* out, NlmScratch& s, int stride) {
    const Planes& img = *g.guide;
    const Planes& var = *g.variance;
    const int w = img.width, h = img.height, F = g.patch_radius;
    const int ex0 = x0 - F, ey0 = y0 - F, ew = (x1 - x0) + 2 * F, eh = (y1 - y0) + 2 * F;
    const size_t area = size_t(ew) * eh;
    s.distance.assign(area * nk, 0.0f);
    s.numerator.resize(ew);
    s.denominator.resize(ew);
    // Whether the patches' extent and its offset copy lie inside the image: then the
    // rows are contiguous and the loop below vectorises; at the border they are clamped.
    const bool inside_x = ex0 >= 0 && ex0 + ew <= w && ex0 + dx >= 0 && ex0 + dx + ew <= w;
    s.column_a.resize(ew);
    s.column_b.resize(ew);
    for (int ex = 0; ex < ew; ++ex) {
        s.column_a[ex] = std::clamp(ex0 + ex, 0, w - 1);
        s.column_b[ex] = std::clamp(ex0 + ex + dx, 0, w - 1);
    }
    // Per-pixel distance over the patches' extent, summed over channels: the squared
    // difference less the variance it carries, over the variance times k^2.
    float* num = s.numerator.data();
    float* den = s.denominator.data();
    for (int c = 0; c < img.channels; ++c) {
        for (int ey = 0; ey < eh; ++ey) {
            const size_t ra = size_t(std::clamp(ey0 + ey, 0, h - 1)) * w;
            const size_t rb = size_t(std::clamp(ey0 + ey + dy, 0, h - 1)) * w;
            const float *ua = img.plane(c) + ra, *ub = img.plane(c) + rb;
            const float *va = var.plane(c) + ra, *vb = var.plane(c) + rb;
            if (inside_x) {
                const float *pa = ua + ex0, *pb = ub + ex0 + dx;
                const float *sa = va + ex0, *sb = vb + ex0 + dx;
                for (int ex = 0; ex < ew; ++ex) {
                    const float diff = pa[ex] - pb[ex];
                    num[ex] = diff * diff - (sa[ex] + std::min(sa[ex], sb[ex]));
                    den[ex] = sa[ex] + sb[ex];
                }
            } else {
                for (int ex = 0; ex < ew; ++ex) {
                    const int xa = s.column_a[ex], xb = s.column_b[ex];
                    const float diff = ua[xa] - ub[xb];
                    num[ex] = diff * diff - (va[xa] + std::min(va[xa], vb[xb]));
                    den[ex] = va[xa] + vb[xb];
                }
            }
            // One division for every bandwidth: num / (k^2 (epsilon + den)).
            for (int ex = 0; ex < ew; ++ex) num[ex] /= kEpsilon + den[ex];
            for (int k = 0; k < nk; ++k) {
                const float inv_k2 = 1.0f / (ks[k] * ks[k]);
                float* d = &s.distance[k * area + size_t(ey) * ew];
                for (int ex = 0; ex < ew; ++ex) d[ex] += num[ex] * inv_k2;
            }
        }
    }
    // Box sums over the patch at the output pixels: columns (contiguous rows, which
    // vectorise), then along the rows.
    const int n = 2 * F + 1;
    const int ow = (x1 - x0 + stride - 1) / stride, oh = (y1 - y0 + stride - 1) / stride;
    const float norm = 1.0f / float(n * n * img.channels);
    for (int k = 0; k < nk; ++k) {
        s.rows.assign(size_t(ew) * oh, 0.0f);
        for (int y = 0; y < oh; ++y) {
            float* r = &s.rows[size_t(y) * ew];
            for (int i = 0; i < n; ++i) {
                const float* d = &s.distance[k * area + size_t(y * stride + i) * ew];
                for (int ex = 0; ex < ew; ++ex) r[ex] += d[ex];
            }
        }
        for (int y = 0; y < oh; ++y) {
            float* o = out[k] + size_t(y) * ow;
            const float* r = &s.rows[size_t(y) * ew];
            std::fill(o, o + ow, 0.0f);
            for (int i = 0; i < n; ++i)
                for (int x = 0; x < ow; ++x) o[x] += r[x * stride + i];
            for (int x = 0; x < ow; ++x) o[x] = exp_neg(std::max(0.0f, o[x] * norm));
            const int yq = y0 + y * stride + dy;
            for (int x = 0; x < ow; ++x) {
                const int xq = x0 + x * stride + dx;
                if (yq < 0 || yq >= h || xq < 0 || xq >= w) o[x] = 0.0f;
            }
        }
    }
}

Planes nl_means(const Planes& image, const NlmGuide& guide, int radius) {
    const int w = image.width, h = image.height, C = image.channels;
    Planes out(w, h, C);
    const int T = kDenoiseTile, tiles_x = (w + T - 1) / T, tiles_y = (h + T - 1) / T;
    tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
        const int x0 = (tile % tiles_x) * T, y0 = (tile / tiles_x) * T;
        const int x1 = std::min(x0 + T, w), y1 = std::min(y0 + T, h), tw = x1 - x0;
        const size_t n = size_t(tw) * (y1 - y0);
        NlmScratch scratch;
        std::vector<float> weights(n), sum(n * C, 0.0f), wsum(n, 0.0f), row(tw);
        std::vector<int> column(tw);
        for (int dy = -radius; dy <= radius; ++dy)
            for (int dx = -radius; dx <= radius; ++dx) {
                float* out_k[1] = {weights.data()};
                patch_weights(guide, &guide.k, 1, x0, y0, x1, y1, dx, dy, out_k, scratch, 1);
                // The weight is 0 where the offset pixel is outside; clamping only keeps
                // the reads inside. Away from the border the offset row is contiguous.
                const bool inside = x0 + dx >= 0 && x1 + dx <= w;
                for (int x = 0; x < tw; ++x) column[x] = std::clamp(x0 + x + dx, 0, w - 1);
                for (int y = y0; y < y1; ++y) {
                    const size_t yq = size_t(std::clamp(y + dy, 0, h - 1)) * w;
                    const float* wt = &weights[size_t(y - y0) * tw];
                    float* ws = &wsum[size_t(y - y0) * tw];
                    for (int x = 0; x < tw; ++x) ws[x] += wt[x];
                    for (int c = 0; c < C; ++c) {
                        const float* in = image.plane(c) + yq;
                        float* acc = &sum[c * n + size_t(y - y0) * tw];
                        if (inside) {
                            const float* q = in + x0 + dx;
                            for (int x = 0; x < tw; ++x) acc[x] += wt[x] * q[x];
                            continue;
                        }
                        for (int x = 0; x < tw; ++x) row[x] = in[column[x]];
                        for (int x = 0; x < tw; ++x) acc[x] += wt[x] * row[x];
                    }
                }
            }
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const size_t i = size_t(y - y0) * tw + (x - x0);
                for (int c = 0; c < C; ++c)
                    out.at(c, x, y) = wsum[i] > 0 ? sum[c * n + i] / wsum[i] : image.at(c, x, y);
            }
    });
    return out;
}

}  // namespace penumbra
