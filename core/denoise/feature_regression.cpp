#include "core/denoise/feature_regression.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/denoise/nl_means.h"
#include "core/error.h"

namespace penumbra {

namespace {

constexpr int kMaxVariables = 16;  // the constant and up to 15 features

// The weight of a pixel's own value beside the fits' predictions (see
// collaborative_regression): e^-7, a patch distance of 7 noise variances.
constexpr float kSelfWeight = 1e-3f;

// A variable whose pivot falls below this fraction of its own weighted sum of squares is
// (numerically) a combination of the others in this window, or constant: it is left out
// of the fit rather than amplifying rounding.
constexpr double kPivotTolerance = 1e-5;
// Ridge, relative to the window's total weight (the features are scaled to unit standard
// deviation over the image first): a fit whose weight sits almost all on its centre has
// next to no information on the slopes, and without it would extrapolate the few
// far-away samples with tiny weights to every pixel it predicts.
constexpr double kRidge = 1e-4;

// Solves (A + ridge) beta = b for the symmetric positive semi-definite A (D x D, upper
// triangle packed row by row) and b (D x 3), dropping dependent variables (their
// coefficients stay 0). Cholesky in double.
void solve(int D, const double* A_packed, const double* b, double* beta) {
    double A[kMaxVariables][kMaxVariables], L[kMaxVariables][kMaxVariables] = {};
    bool active[kMaxVariables];
    for (int i = 0, m = 0; i < D; ++i)
        for (int j = i; j < D; ++j, ++m) A[i][j] = A[j][i] = A_packed[m];
    for (int i = 1; i < D; ++i) A[i][i] += kRidge * A[0][0];
    for (int k = 0; k < D; ++k) {
        double d = A[k][k];
        for (int m = 0; m < k; ++m) d -= L[k][m] * L[k][m];
        active[k] = A[k][k] > 0 && d > kPivotTolerance * A[k][k];
        if (!active[k]) continue;
        L[k][k] = std::sqrt(d);
        for (int i = k + 1; i < D; ++i) {
            double s = A[i][k];
            for (int m = 0; m < k; ++m) s -= L[i][m] * L[k][m];
            L[i][k] = s / L[k][k];
        }
    }
    for (int c = 0; c < 3; ++c) {
        double z[kMaxVariables];
        for (int i = 0; i < D; ++i) {
            z[i] = 0;
            if (!active[i]) continue;
            double s = b[i * 3 + c];
            for (int m = 0; m < i; ++m) s -= L[i][m] * z[m];
            z[i] = s / L[i][i];
        }
        for (int i = D - 1; i >= 0; --i) {
            double s = 0;
            if (active[i]) {
                s = z[i];
                for (int m = i + 1; m < D; ++m) s -= L[m][i] * beta[m * 3 + c];
                s /= L[i][i];
            }
            beta[i * 3 + c] = s;
        }
    }
}

struct Tile {
    int x0, y0, x1, y1;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    size_t pixels() const { return size_t(width()) * height(); }
};

// One tile's fits, per bandwidth: the predictions they make over the tile grown by R,
// summed (colour and weight planes).
struct TileFit {
    std::vector<std::vector<float>> predictions;  // per bandwidth, 4 planes of (w + 2R) x (h + 2R)
};

// The solution of each centre's fit from its normal equations (ata: D(D+1)/2 planes of
// n, atb: 3D planes): the constant term per channel, then the features' coefficients,
// as 3D planes of n.
std::vector<float> solve_fits(const std::vector<float>& ata, const std::vector<float>& atb, int D,
                              size_t n) {
    const int M = D * (D + 1) / 2;
    std::vector<float> beta(size_t(D) * 3 * n);
    for (size_t i = 0; i < n; ++i) {
        double a[kMaxVariables * (kMaxVariables + 1) / 2], rhs[kMaxVariables * 3],
            sol[kMaxVariables * 3];
        for (int m = 0; m < M; ++m) a[m] = ata[size_t(m) * n + i];
        for (int m = 0; m < D * 3; ++m) rhs[m] = atb[size_t(m) * n + i];
        solve(D, a, rhs, sol);
        for (int m = 0; m < D * 3; ++m) beta[size_t(m) * n + i] = float(sol[m]);
    }
    return beta;
}

// Every fit of the tile (cw x ch centres, their features in `centre`) predicts its window,
// weighted as in the fit: the constant term plus the coefficients times the features'
// difference from the centre, summed into pred (colour and weight planes over the tile
// grown by R).
void add_predictions(const Planes& features, const RegressionParams& p, const Tile& t, int cw,
                     int ch, const std::vector<float>& centre, const std::vector<float>& weights,
                     const std::vector<float>& beta, std::vector<float>& pred) {
    const int w = features.width, h = features.height, R = p.window_radius;
    const int S = p.center_stride, Fc = features.channels, pw = t.width() + 2 * R;
    const size_t n = size_t(cw) * ch, pn = size_t(pw) * (t.height() + 2 * R);
    for (int dy = -R, o = 0; dy <= R; ++dy)
        for (int dx = -R; dx <= R; ++dx, ++o) {
            const float* wt = &weights[size_t(o) * n];
            for (int j = 0; j < ch; ++j) {
                const int yq = t.y0 + j * S + dy;
                if (yq < 0 || yq >= h) continue;
                for (int i = 0; i < cw; ++i) {
                    const int xq = t.x0 + i * S + dx;
                    const size_t ci = size_t(j) * cw + i;
                    const float wgt = wt[ci];
                    if (xq < 0 || xq >= w || wgt == 0) continue;
                    const size_t pi = size_t(yq - t.y0 + R) * pw + (xq - t.x0 + R);
                    float r[3] = {beta[0 * n + ci], beta[1 * n + ci], beta[2 * n + ci]};
                    for (int k = 0; k < Fc; ++k) {
                        const float df = features.at(k, xq, yq) - centre[size_t(k) * n + ci];
                        for (int c = 0; c < 3; ++c)
                            r[c] += beta[size_t((k + 1) * 3 + c) * n + ci] * df;
                    }
                    for (int c = 0; c < 3; ++c) pred[c * pn + pi] += wgt * r[c];
                    pred[3 * pn + pi] += wgt;
                }
            }
        }
}

TileFit fit_tile(const Planes& color, const Planes& variance, const Planes& features,
                 const RegressionParams& p, const std::vector<float>& ks, const Tile& t) {
    const int w = color.width, h = color.height, R = p.window_radius, S = p.center_stride;
    const int Fc = features.channels, D = 1 + Fc, M = D * (D + 1) / 2, K = int(ks.size());
    const int side = 2 * R + 1;
    // The fits' centres: every S-th pixel of every S-th row (tile corners are multiples of S).
    const int cw = (t.width() + S - 1) / S, ch = (t.height() + S - 1) / S;
    const size_t n = size_t(cw) * ch, offsets = size_t(side) * side;
    const NlmGuide guide{&color, &variance, p.patch_radius, 0};
    NlmScratch scratch;
    // Per bandwidth: the weights of every offset, and the normal equations.
    std::vector<std::vector<float>> weights(K), ata(K), atb(K);
    for (int b = 0; b < K; ++b) {
        weights[b].resize(offsets * n);
        ata[b].assign(size_t(M) * n, 0.0f);
        atb[b].assign(size_t(D) * 3 * n, 0.0f);
    }
    std::vector<float> X(size_t(D) * cw), WX(size_t(D) * cw), Y(size_t(3) * cw);
    std::vector<float> centre(size_t(Fc) * n);  // the features at the centres
    for (int k = 0; k < Fc; ++k)
        for (int j = 0; j < ch; ++j)
            for (int i = 0; i < cw; ++i)
                centre[size_t(k) * n + size_t(j) * cw + i] =
                    features.at(k, t.x0 + i * S, t.y0 + j * S);
    std::vector<size_t> column(cw);
    for (int dy = -R, o = 0; dy <= R; ++dy)
        for (int dx = -R; dx <= R; ++dx, ++o) {
            float* wts[4];
            for (int b = 0; b < K; ++b) wts[b] = &weights[b][size_t(o) * n];
            patch_weights(guide, ks.data(), K, t.x0, t.y0, t.x1, t.y1, dx, dy, wts, scratch, S);
            for (int i = 0; i < cw; ++i)
                column[i] = size_t(std::clamp(t.x0 + i * S + dx, 0, w - 1));
            for (int j = 0; j < ch; ++j) {
                const size_t row = size_t(j) * cw;
                const size_t qrow = size_t(std::clamp(t.y0 + j * S + dy, 0, h - 1)) * w;
                // The samples' variables (1, then the features less the centre's) and colour.
                for (int i = 0; i < cw; ++i) X[i] = 1.0f;
                for (int k = 0; k < Fc; ++k) {
                    const float* f = features.plane(k) + qrow;
                    const float* fc = &centre[size_t(k) * n + row];
                    float* x = &X[size_t(k + 1) * cw];
                    for (int i = 0; i < cw; ++i) x[i] = f[column[i]] - fc[i];
                }
                for (int c = 0; c < 3; ++c) {
                    const float* col = color.plane(c) + qrow;
                    for (int i = 0; i < cw; ++i) Y[size_t(c) * cw + i] = col[column[i]];
                }
                for (int b = 0; b < K; ++b) {
                    const float* wt = wts[b] + row;
                    for (int k = 0; k < D; ++k)
                        for (int i = 0; i < cw; ++i)
                            WX[size_t(k) * cw + i] = wt[i] * X[size_t(k) * cw + i];
                    for (int k = 0, m = 0; k < D; ++k)
                        for (int l = k; l < D; ++l, ++m) {
                            float* a = &ata[b][size_t(m) * n + row];
                            const float *wk = &WX[size_t(k) * cw], *xl = &X[size_t(l) * cw];
                            for (int i = 0; i < cw; ++i) a[i] += wk[i] * xl[i];
                        }
                    for (int k = 0; k < D; ++k)
                        for (int c = 0; c < 3; ++c) {
                            float* a = &atb[b][size_t(k * 3 + c) * n + row];
                            const float *wk = &WX[size_t(k) * cw], *yc = &Y[size_t(c) * cw];
                            for (int i = 0; i < cw; ++i) a[i] += wk[i] * yc[i];
                        }
                }
            }
        }
    TileFit fit;
    const size_t pn = size_t(t.width() + 2 * R) * (t.height() + 2 * R);
    for (int b = 0; b < K; ++b) {
        const std::vector<float> beta = solve_fits(ata[b], atb[b], D, n);
        std::vector<float>& pred = fit.predictions.emplace_back(4 * pn, 0.0f);
        add_predictions(features, p, t, cw, ch, centre, weights[b], beta, pred);
    }
    return fit;
}

// Each feature divided by its standard deviation over the image (constant ones are left
// as they are), so that the ridge weighs all alike.
Planes unit_scaled(const Planes& features) {
    Planes out = features;
    const size_t n = features.pixels();
    for (int k = 0; k < features.channels; ++k) {
        double sum = 0, sum2 = 0;
        for (size_t i = 0; i < n; ++i) {
            sum += features.plane(k)[i];
            sum2 += double(features.plane(k)[i]) * features.plane(k)[i];
        }
        const double mean = sum / double(n), var = sum2 / double(n) - mean * mean;
        if (!(var > 0)) continue;
        const float inv = float(1 / std::sqrt(var));
        for (size_t i = 0; i < n; ++i) out.plane(k)[i] *= inv;
    }
    return out;
}

}  // namespace

std::vector<Planes> collaborative_regression(const Planes& color, const Planes& variance,
                                             const Planes& features, const RegressionParams& p,
                                             const std::vector<float>& ks) {
    const int w = color.width, h = color.height, R = p.window_radius, S = p.center_stride;
    const int K = int(ks.size());
    CHECK(K >= 1 && K <= 4, "one to four bandwidths");
    const Planes scaled = unit_scaled(features);
    const int T = std::max(kDenoiseTile, R);  // a pixel lies in the grown tiles of 3 x 3
    const int tiles_x = (w + T - 1) / T, tiles_y = (h + T - 1) / T;
    auto tile_at = [&](int tx, int ty) {
        return Tile{tx * T, ty * T, std::min(tx * T + T, w), std::min(ty * T + T, h)};
    };
    std::vector<TileFit> fits(size_t(tiles_x) * tiles_y);
    tbb::parallel_for(0, tiles_x * tiles_y, [&](int i) {
        fits[i] = fit_tile(color, variance, scaled, p, ks, tile_at(i % tiles_x, i / tiles_x));
    });
    // Each pixel sums the predictions of the tiles around it, in tile order.
    std::vector<Planes> out(K, Planes(w, h, 3));
    tbb::parallel_for(0, tiles_x * tiles_y, [&](int i) {
        const Tile t = tile_at(i % tiles_x, i / tiles_x);
        for (int b = 0; b < K; ++b)
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) {
                    float sum[4] = {0, 0, 0, 0};
                    for (int ty = std::max(0, y / T - 1); ty <= std::min(tiles_y - 1, y / T + 1);
                         ++ty)
                        for (int tx = std::max(0, x / T - 1);
                             tx <= std::min(tiles_x - 1, x / T + 1); ++tx) {
                            const Tile s = tile_at(tx, ty);
                            const int pw = s.width() + 2 * R, ph = s.height() + 2 * R;
                            const int px = x - s.x0 + R, py = y - s.y0 + R;
                            if (px < 0 || py < 0 || px >= pw || py >= ph) continue;
                            const size_t pn = size_t(pw) * ph, pi = size_t(py) * pw + px;
                            const std::vector<float>& pred = fits[ty * tiles_x + tx].predictions[b];
                            for (int c = 0; c < 4; ++c) sum[c] += pred[c * pn + pi];
                        }
                    // The pixel's own value counts too, with a weight far below what the
                    // fits give it wherever they see it (a fit's centre gives itself 1):
                    // where the colour is nearly noise-free the weights of every other
                    // pixel vanish, and a pixel between the fits' centres would otherwise
                    // be left to the vanishing tails of fits that do not see it.
                    const float self = S > 1 ? kSelfWeight : 0.0f;
                    for (int c = 0; c < 3; ++c)
                        out[b].at(c, x, y) = (sum[c] + self * color.at(c, x, y)) / (sum[3] + self);
                }
    });
    return out;
}

}  // namespace penumbra
