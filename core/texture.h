// A glTF texture: an image plus its sampler (wrap modes, filters). Lookups take glTF
// texture coordinates (origin at the top-left of the image, v down) and a footprint
// width in the same units, and return linear RGBA in the scene's working space.
#pragma once

#include <cstdint>

#include "core/math/vec.h"
#include "core/texture_image.h"

namespace penumbra {

enum class WrapMode { Repeat, ClampToEdge, MirroredRepeat };
// The mipmap part of glTF's minFilter: none (NEAREST, LINEAR), the nearest level
// (*_MIPMAP_NEAREST) or between the two nearest levels (*_MIPMAP_LINEAR, and the
// default when the sampler leaves minFilter out).
enum class MipFilter { None, Nearest, Linear };

struct Texture {
    uint32_t image = 0;  // index into Scene::images
    WrapMode wrap_s = WrapMode::Repeat;
    WrapMode wrap_t = WrapMode::Repeat;
    bool nearest = false;      // magFilter NEAREST; otherwise bilinear
    bool min_nearest = false;  // minFilter NEAREST or NEAREST_MIPMAP_*: texels unfiltered
    MipFilter mip = MipFilter::Linear;
};

// The level of detail for a footprint `width` uv units wide: log2 of its width in
// texels of level 0 (Akenine-Moller et al. 2021, eq. 34: 0.5 log2(w h) for the texture's
// size). <= 0 magnifies; -infinity for a point.
float texture_lod(const TextureImage& img, float width);

// The texture over a footprint `width` wide (0: a point, level 0 with the magnification
// filter, as a lookup without a ray cone): trilinear, or as the sampler's filters say,
// with the wrap modes at every level; then the image's working-space matrix.
Vec4 lookup(const Texture& tex, const TextureImage& img, Vec2 uv, float width = 0);

}  // namespace penumbra
