#include "support/accel_scenes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/sampling/rng.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/scene_builder.h"

namespace penumbra::test {

TriangleMesh make_sphere_mesh(Vec3 center, float radius, int slices, int stacks) {
    TriangleMesh m;
    m.name = "sphere";
    m.positions.push_back(center + Vec3(0, radius, 0));
    for (int i = 1; i < stacks; ++i) {
        const float theta = kPi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const float phi = 2 * kPi * j / slices;
            m.positions.push_back(center + radius * Vec3(std::sin(theta) * std::cos(phi),
                                                         std::cos(theta),
                                                         std::sin(theta) * std::sin(phi)));
        }
    }
    m.positions.push_back(center + Vec3(0, -radius, 0));
    const uint32_t south = static_cast<uint32_t>(m.positions.size() - 1);
    auto ring = [&](int i, int j) { return uint32_t(1 + (i - 1) * slices + (j % slices)); };
    for (int j = 0; j < slices; ++j) {
        m.indices.insert(m.indices.end(), {0u, ring(1, j + 1), ring(1, j)});
        m.indices.insert(m.indices.end(), {south, ring(stacks - 1, j), ring(stacks - 1, j + 1)});
    }
    for (int i = 1; i < stacks - 1; ++i)
        for (int j = 0; j < slices; ++j) {
            const uint32_t a = ring(i, j), b = ring(i, j + 1), c = ring(i + 1, j + 1),
                           d = ring(i + 1, j);
            m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
    for (const Vec3& p : m.positions) m.bounds.expand(p);
    return m;
}

uint32_t add_sphere_object(Scene& scene, Vec3 center, float radius, int slices, int stacks) {
    scene.meshes.push_back(make_sphere_mesh(center, radius, slices, stacks));
    Object obj;
    obj.name = "sphere";
    obj.meshes.push_back(static_cast<uint32_t>(scene.meshes.size() - 1));
    obj.bounds = scene.meshes.back().bounds;
    scene.objects.push_back(obj);
    return static_cast<uint32_t>(scene.objects.size() - 1);
}

Scene make_instanced_spheres(int n, uint64_t seed) {
    Scene scene;
    const uint32_t sphere = add_sphere_object(scene, Vec3(0.0f), 0.5f, 24, 12);
    const uint32_t cube = add_cube_object(scene, -1);
    Rng rng(seed);
    auto u = [&] { return rng.next_float(); };
    for (int i = 0; i < n; ++i) {
        Quat q{u() - 0.5f, u() - 0.5f, u() - 0.5f, u() - 0.5f};
        Vec3 s(0.3f + u(), 0.3f + u(), 0.3f + 2 * u());  // non-uniform
        if (i % 3 == 0) s.x = -s.x;                      // mirrored
        if (i % 5 == 0) s = Vec3(0.7f, -0.7f, -0.7f);    // mirrored twice over
        const Vec3 t(10 * u() - 5, 10 * u() - 5, 10 * u() - 5);
        add_instance(scene, i % 4 == 3 ? cube : sphere, Transform::trs(t, q, s));
    }
    return scene;
}

const Scene& cornell_box() {
    static const Scene scene = load_gltf(source_path("scenes/cornell-box.gltf"));
    return scene;
}

const std::vector<std::pair<std::string, Scene>>& khronos_scenes() {
    static const std::vector<std::pair<std::string, Scene>> scenes = [] {
        std::vector<std::string> paths;
        for (const auto& e : std::filesystem::directory_iterator(shared_path("scenes/khronos")))
            if (e.path().extension() == ".gltf") paths.push_back(e.path().string());
        std::sort(paths.begin(), paths.end());
        std::vector<std::pair<std::string, Scene>> out;
        for (const std::string& p : paths) out.emplace_back(p, load_gltf(p));
        return out;
    }();
    return scenes;
}

}  // namespace penumbra::test
