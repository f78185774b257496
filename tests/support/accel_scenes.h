// Meshes and scenes for the accelerator tests: closed spheres for watertightness, a
// scene of many transformed instances, and the Cornell box and Khronos files loaded
// once per test process.
#pragma once

#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace penumbra::test {

// A closed UV sphere (shared vertices, poles as single vertices) of the given radius
// around center, as an object; returns the object index. 2 * slices * (stacks - 1)
// triangles.
uint32_t add_sphere_object(Scene& scene, Vec3 center, float radius, int slices, int stacks);
// The same sphere as a bare mesh (for builders and benchmarks).
TriangleMesh make_sphere_mesh(Vec3 center, float radius, int slices, int stacks);
// n instances of one sphere with random rotations, non-uniform and mirrored (negative)
// scales and translations spread over a box of side ~10.
Scene make_instanced_spheres(int n, uint64_t seed);
// The repository's scenes/cornell-box.gltf.
const Scene& cornell_box();
// Every .gltf under shared/scenes/khronos, path and scene.
const std::vector<std::pair<std::string, Scene>>& khronos_scenes();

}  // namespace penumbra::test
