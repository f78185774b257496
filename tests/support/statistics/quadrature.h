// Numerical integration for tests: globally adaptive Gauss-Kronrod (QUADPACK's qag),
// which resolves narrow peaks (GGX lobes at small alpha) and jumps (the edge of a
// uniform density) that fixed rules miss.
#pragma once

#include <functional>

namespace penumbra::test {

// The integral of f over [a, b]. Keeps splitting the panel with the largest error
// estimate until the total estimate is below max(tol, rel_tol |integral|) or max_panels
// panels are in use. The relative part matters for float integrands: rounding noise
// puts a floor of about 1e-6 |integral| under the error estimate, which an absolute
// tolerance alone would chase until the budget runs out.
double integrate_1d(const std::function<double(double)>& f, double a, double b, double tol,
                    double rel_tol = 1e-5, int initial_panels = 4, int max_panels = 200);

// The integral of f(x, y) over [x0, x1] x [y0, y1], y innermost, to an absolute
// tolerance tol or a relative one of 1e-5.
double integrate_2d(const std::function<double(double, double)>& f, double x0, double x1, double y0,
                    double y1, double tol);

}  // namespace penumbra::test
