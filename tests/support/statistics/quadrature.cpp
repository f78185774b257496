#include "support/statistics/quadrature.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace penumbra::test {

namespace {

// Gauss-Kronrod 7-15 nodes and weights on [-1, 1] (QUADPACK qk15).
constexpr double kXgk[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr double kWgk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975,
                           0.417959183673469387755102040816327};

struct Panel {
    double a, b, value, error;
    bool operator<(const Panel& o) const { return error < o.error; }
};

Panel gauss_kronrod(const std::function<double(double)>& f, double a, double b) {
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    const double fc = f(c);
    double kronrod = fc * kWgk[7], gauss = fc * kWg[3];
    for (int j = 0; j < 7; ++j) {
        const double f1 = f(c - h * kXgk[j]), f2 = f(c + h * kXgk[j]);
        kronrod += kWgk[j] * (f1 + f2);
        if (j % 2 == 1) gauss += kWg[j / 2] * (f1 + f2);
    }
    return {a, b, kronrod * h, std::abs((kronrod - gauss) * h)};
}

}  // namespace

double integrate_1d(const std::function<double(double)>& f, double a, double b, double tol,
                    double rel_tol, int initial_panels, int max_panels) {
    std::priority_queue<Panel> panels;
    double value = 0, error = 0;
    for (int i = 0; i < initial_panels; ++i) {
        const Panel p = gauss_kronrod(f, a + (b - a) * i / initial_panels,
                                      a + (b - a) * (i + 1) / initial_panels);
        value += p.value;
        error += p.error;
        panels.push(p);
    }
    for (int n = initial_panels; n < max_panels && error > std::max(tol, rel_tol * std::abs(value));
         ++n) {
        const Panel worst = panels.top();
        panels.pop();
        const double m = 0.5 * (worst.a + worst.b);
        const Panel l = gauss_kronrod(f, worst.a, m), r = gauss_kronrod(f, m, worst.b);
        value += l.value + r.value - worst.value;
        error += l.error + r.error - worst.error;
        panels.push(l);
        panels.push(r);
    }
    return value;
}

double integrate_2d(const std::function<double(double, double)>& f, double x0, double x1, double y0,
                    double y1, double tol) {
    // The inner error, integrated over x, must stay well inside the outer tolerance.
    const double inner_tol = 0.1 * tol / (x1 - x0);
    return integrate_1d(
        [&](double x) {
            return integrate_1d([&](double y) { return f(x, y); }, y0, y1, inner_tol, 1e-6, 2);
        },
        x0, x1, tol, 1e-5);
}

}  // namespace penumbra::test
