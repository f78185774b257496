// Small scenes built in code for tests that need exact geometry without a file.
#pragma once

#include <string>

#include "core/scene/scene.h"

namespace penumbra::test {

// Adds an object made of one mesh (its bounds and name filled in); returns its index.
uint32_t add_mesh_object(Scene& scene, TriangleMesh mesh, const std::string& name);
// Adds an object made of one mesh (a quad of two triangles, corners counter-clockwise as
// seen from its front) and returns the object index. No instance is created.
uint32_t add_quad_object(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, int material);
// Adds the closed cube [-0.5, 0.5]^3 (outward winding) as an object.
uint32_t add_cube_object(Scene& scene, int material);
// Adds a UV sphere of radius 1 at the origin (smooth normals) as an object.
uint32_t add_sphere_object(Scene& scene, int material, int rings = 24, int segments = 48);
// Places object `object` with to_world; returns the instance index.
uint32_t add_instance(Scene& scene, uint32_t object, const Transform& to_world);
// A material that is exactly Lambertian with the given albedo.
int add_lambertian(Scene& scene, Spectrum albedo);
// A Lambertian sphere (12 x 24) on a floor under a point light: edges and indirect light,
// so every sample and every pixel differs (for render-loop tests).
Scene make_lit_sphere_on_floor();

}  // namespace penumbra::test
