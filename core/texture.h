// A glTF texture: an image plus its sampler (wrap modes, filtering). Lookups take glTF
// texture coordinates (origin at the top-left of the image, v down) and return linear
// RGBA: colour images were converted from sRGB when they were loaded.
#pragma once

#include <cstdint>

#include "core/image.h"
#include "core/math/vec.h"

namespace penumbra {

enum class WrapMode { Repeat, ClampToEdge, MirroredRepeat };

struct Texture {
    uint32_t image = 0;  // index into Scene::images
    WrapMode wrap_s = WrapMode::Repeat;
    WrapMode wrap_t = WrapMode::Repeat;
    bool nearest = false;  // glTF magFilter NEAREST; otherwise bilinear
};

// Bilinear (or nearest) lookup with the texture's wrap modes.
Vec4 lookup(const Texture& tex, const Image& img, Vec2 uv);

}  // namespace penumbra
