// What the denoiser reads: the beauty's two independently seeded halves, the guide
// features of each half, and the variances of the full means. Float images, so the
// input is the same numbers whether it comes straight from the film or back from band
// EXRs: a farm's merge denoises to the bits one machine writes.
#pragma once

#include "core/image.h"

namespace penumbra {

// Guide feature channels, in this order: albedo R, G, B; shading normal X, Y, Z; depth;
// visibility. They describe the first non-specular surface a camera sample reaches
// (through mirrors and smooth glass, as Cycles' and OIDN's guides do), the albedo tinted
// by the specular surfaces on the way; visibility is whether one light sample from there
// is unoccluded (NFOR's visibility feature: it carries shadow edges, which no other guide
// does). A sample that escapes counts as zero in all eight.
inline constexpr int kGuideChannels = 8;
inline constexpr int kGuideAlbedo = 0, kGuideNormal = 3, kGuideDepth = 6, kGuideVisibility = 7;

struct DenoiseInput {
    Image color_a, color_b;  // 3 channels: the means of the even and odd samples
    Image color_variance;    // 3: the variance of the pixel's full mean
    Image guide_a, guide_b;  // kGuideChannels: the halves' guide means
    Image guide_variance;    // kGuideChannels: the variance of the full mean
    int width() const { return color_a.width; }
    int height() const { return color_a.height; }
};

}  // namespace penumbra
