// Renders a whole Scene in one call for tests that check images (the hard cases in
// scenes/hard/): Embree, the scene's lights, a box filter, no progress output.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/camera/camera.h"
#include "core/image.h"
#include "core/lights/environment_light.h"
#include "core/scene/scene.h"

namespace penumbra::test {

struct SceneRender {
    Image image;  // RGBA, resolved
    uint64_t nonfinite_samples = 0;
};

SceneRender render_scene(const Scene& scene, const Camera& camera, const std::string& integrator,
                         uint32_t spp, uint64_t seed = 0, int max_depth = 5,
                         std::unique_ptr<EnvironmentLight> environment = nullptr);

// Moves the whole scene (instances and cameras) by `xf`, applied after their own
// transforms. Lights other than directional ones are not moved.
void transform_scene(Scene& scene, const Transform& xf);

// Luminance-free helpers over an image's RGB: the pixel's mean of R, G, B.
float pixel_mean(const Image& img, int x, int y);

}  // namespace penumbra::test
