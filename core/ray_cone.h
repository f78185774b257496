// Ray cones for texture filtering (Akenine-Moller et al., "Improved Shader and Texture
// Level of Detail Using Ray Cones", JCGT 10(1), 2021): a width and a spread angle that
// each ray carries, so a hit knows the footprint its texture lookups average over.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math/vec.h"

namespace penumbra {

struct RayCone {
    float width = 0;   // world-space width at the ray's origin
    float spread = 0;  // radians: the width grows by spread per unit of distance
    bool active() const { return width > 0 || spread > 0; }
    float width_at(float dist) const { return width + spread * dist; }
};

// The cone of a ray leaving a hit whose footprint is width_at_hit wide. A specular
// bounce keeps the spread (the paper's planar mirror; surface curvature is not used,
// so a curved mirror's footprint is underestimated: a finer level, never blur). A
// sampled non-specular direction widens it by the angle of the cone whose solid angle
// is 1/pdf, the share of the lobe one sample stands for (after Suykens and Willems,
// "Path differentials and applications", EGWR 2001): narrow lobes add little, a
// Lambertian bounce about 2 radians. Capped at pi: beyond that every level is the mean.
inline RayCone bounce_cone(const RayCone& in, float width_at_hit, float pdf, bool specular) {
    RayCone out{width_at_hit, in.spread};
    if (!specular && pdf > 0 && in.active())
        out.spread = std::min(kPi, in.spread + 2 / std::sqrt(kPi * pdf));
    return out;
}

}  // namespace penumbra
