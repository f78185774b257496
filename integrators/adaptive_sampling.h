// Adaptive sampling to a relative error target: which pixels still take samples after
// each pass, decided only from the film after whole passes (never from timing), so the
// image stays bitwise identical across thread counts.
#pragma once

#include <cstdint>
#include <vector>

#include "core/film/film.h"

namespace penumbra {

// The samples every pixel takes before its error is trusted: Cycles' automatic rule,
// 16 / E^0.3 (64 at E = 0.01), at least 8, rounded up to an even count so both halves
// of the estimate hold the same number of samples.
uint32_t adaptive_min_spp(double target_error);

// The samples of the next pass when `done` are done (even, >= 2): a quarter of those
// done, at least 16, so checks come often at first and cost little later. Both halves
// grow alike because every pass is even and starts at an even index.
uint32_t adaptive_step(uint32_t done);

// The per-pixel decision after a pass. A window (a pixel's 3x3 neighbourhood) is
// converged when the mean of relative_error^2 over it is below target_error^2: one
// pixel's estimate has a single degree of freedom per channel (chi-square(1) puts a
// quarter of its mass below a tenth of its mean), the window about nine. A pixel stays
// active while any window it belongs to is not converged (dilation, as Cycles does).
// Stopping when the estimate is low favours samples whose halves happen to agree, so
// the adaptive image is slightly biased, as Cycles' is (docs/performance.md measures
// it). Leaving a pixel's own error out of its decision removes that bias but deadlocks:
// a firefly pixel stops while its stale error keeps its 24 neighbours at the budget.
// Returns the count of active pixels.
size_t update_active_pixels(const Film& film, double target_error, std::vector<uint8_t>& active);

}  // namespace penumbra
