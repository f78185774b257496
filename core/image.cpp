#include "core/image.h"

namespace penumbra {

Vec4 Image::rgba(int x, int y) const {
    const float* p = at(x, y);
    switch (channels) {
        case 1: return {p[0], p[0], p[0], 1};
        case 2: return {p[0], p[0], p[0], p[1]};
        case 3: return {p[0], p[1], p[2], 1};
        default: return {p[0], p[1], p[2], p[3]};
    }
}

}  // namespace penumbra
