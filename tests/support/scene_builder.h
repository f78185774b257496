// Small scenes built in code for tests that need exact geometry without a file.
#pragma once

#include <string>

#include "core/scene/scene.h"

namespace penumbra::test {

// Adds an object made of one mesh (a quad of two triangles, corners counter-clockwise as
// seen from its front) and returns the object index. No instance is created.
uint32_t add_quad_object(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, int material);
// Adds the closed cube [-0.5, 0.5]^3 (outward winding) as an object.
uint32_t add_cube_object(Scene& scene, int material);
// Places object `object` with to_world; returns the instance index.
uint32_t add_instance(Scene& scene, uint32_t object, const Transform& to_world);
// A material that is exactly Lambertian with the given albedo.
int add_lambertian(Scene& scene, Spectrum albedo);

}  // namespace penumbra::test
