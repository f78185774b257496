#include "core/camera/camera.h"

#include "core/camera/moving_camera.h"
#include "core/camera/orthographic_camera.h"
#include "core/camera/perspective_camera.h"
#include "core/camera/stepped_camera.h"
#include "core/camera/thin_lens_camera.h"

namespace penumbra {

std::unique_ptr<Camera> make_camera(const CameraDesc& desc, int width, int height) {
    if (!desc.view_steps.empty()) {
        // One camera per field of view, each with the whole motion.
        std::vector<std::unique_ptr<Camera>> steps;
        for (float view : desc.view_steps) {
            CameraDesc step = desc;
            step.view_steps.clear();
            (desc.type == ProjectionType::Orthographic ? step.ymag : step.yfov) = view;
            steps.push_back(make_camera(step, width, height));
        }
        return std::make_unique<SteppedCamera>(std::move(steps));
    }
    if (!desc.motion.empty()) {
        // The same camera in its own frame, moved per sample.
        CameraDesc local = desc;
        local.to_world = Transform();
        local.motion.clear();
        return std::make_unique<MovingCamera>(make_camera(local, width, height), desc.motion);
    }
    if (desc.type == ProjectionType::Orthographic) {
        // Keep the vertical extent; the horizontal one follows the image so that pixels
        // stay square even when the file's xmag/ymag ratio differs from the image's.
        const float xmag = desc.ymag * static_cast<float>(width) / static_cast<float>(height);
        return std::make_unique<OrthographicCamera>(desc.to_world, xmag, desc.ymag, width,
                                                    height);
    }
    if (desc.aperture_radius > 0 && desc.focus_distance > 0)
        return std::make_unique<ThinLensCamera>(desc.to_world, desc.yfov, width, height,
                                                desc.aperture_radius, desc.focus_distance,
                                                desc.aperture_blades, desc.blade_rotation);
    return std::make_unique<PerspectiveCamera>(desc.to_world, desc.yfov, width, height);
}

}  // namespace penumbra
