// Fireflies: rare samples thousands of times the pixel's mean (caustic paths, small
// bright sources seen through glossy bounces). In one half's mean they stand alone;
// left in, the non-local means weights, which allow for a pixel's own huge variance,
// would spread each over its neighbours as a blotch. A value is held back when it is far
// above the median of its surroundings in both halves, above the other half's value at
// the same pixel, and above the image's mean level: a real small bright feature shows
// in both halves and is kept.
#pragma once

#include <cstddef>

#include "core/denoise/planes.h"

namespace penumbra {

// How far above its surroundings a value may be: more is a firefly.
inline constexpr float kFireflyRatio = 4.0f;

// Scales each firefly in a and b (3 channels each, compared by their largest channel)
// down to kFireflyRatio times that limit, and sets the pixel's variance (of the full mean, 3
// channels) to the halves' squared difference over 4, now that its own sample variance
// holds the firefly. Returns how many half-pixels were scaled.
size_t guard_fireflies(Planes& a, Planes& b, Planes& variance);

}  // namespace penumbra
