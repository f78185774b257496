#include "core/camera/camera.h"

#include "core/camera/orthographic_camera.h"
#include "core/camera/perspective_camera.h"

namespace penumbra {

std::unique_ptr<Camera> make_camera(const CameraDesc& desc, int width, int height) {
    if (desc.type == ProjectionType::Orthographic) {
        // Keep the vertical extent; the horizontal one follows the image so that pixels
        // stay square even when the file's xmag/ymag ratio differs from the image's.
        const float xmag = desc.ymag * static_cast<float>(width) / static_cast<float>(height);
        return std::make_unique<OrthographicCamera>(desc.to_world, xmag, desc.ymag, width,
                                                    height);
    }
    return std::make_unique<PerspectiveCamera>(desc.to_world, desc.yfov, width, height);
}

}  // namespace penumbra
