#include "support/scene_builder.h"

#include <cmath>
#include <memory>

#include "core/lights/point_light.h"

namespace penumbra::test {

uint32_t add_mesh_object(Scene& scene, TriangleMesh mesh, const std::string& name) {
    for (const Vec3& p : mesh.positions) mesh.bounds.expand(p);
    mesh.name = name;
    scene.meshes.push_back(std::move(mesh));
    Object obj;
    obj.name = name;
    obj.meshes.push_back(static_cast<uint32_t>(scene.meshes.size() - 1));
    obj.bounds = scene.meshes.back().bounds;
    scene.objects.push_back(obj);
    return static_cast<uint32_t>(scene.objects.size() - 1);
}

uint32_t add_quad_object(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, int material) {
    TriangleMesh m;
    m.positions = {a, b, c, d};
    const Vec3 n = normalize(cross(b - a, c - a));
    m.normals = {n, n, n, n};
    m.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.material = material;
    return add_mesh_object(scene, std::move(m), "quad");
}

uint32_t add_cube_object(Scene& scene, int material) {
    TriangleMesh m;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const uint32_t base = static_cast<uint32_t>(m.positions.size());
            const int corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (const auto& c : corners) {
                Vec3 p;
                p[axis] = 0.5f * sign;
                p[u] = 0.5f * c[0];
                p[v] = 0.5f * c[1] * sign;
                m.positions.push_back(p);
                Vec3 n;
                n[axis] = static_cast<float>(sign);
                m.normals.push_back(n);
            }
            for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
        }
    m.material = material;
    return add_mesh_object(scene, std::move(m), "cube");
}

uint32_t add_sphere_object(Scene& scene, int material, int rings, int segments) {
    TriangleMesh m;
    for (int r = 0; r <= rings; ++r) {
        const float theta = kPi * r / rings;
        for (int s = 0; s <= segments; ++s) {
            const float phi = 2 * kPi * s / segments;
            const Vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                         -std::sin(theta) * std::sin(phi));
            m.positions.push_back(n);
            m.normals.push_back(n);
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            if (r != 0) m.indices.insert(m.indices.end(), {a, b, a + 1});
            if (r != rings - 1) m.indices.insert(m.indices.end(), {a + 1, b, b + 1});
        }
    m.material = material;
    return add_mesh_object(scene, std::move(m), "sphere");
}

uint32_t add_instance(Scene& scene, uint32_t object, const Transform& to_world) {
    Instance inst;
    inst.object = object;
    inst.to_world = to_world;
    inst.name = "instance" + std::to_string(scene.instances.size());
    scene.instances.push_back(inst);
    return static_cast<uint32_t>(scene.instances.size() - 1);
}

int add_lambertian(Scene& scene, Spectrum albedo) {
    MaterialDesc m;
    m.base_color = Vec4(albedo, 1);
    m.metallic = 0;
    m.specular = 0;
    scene.materials.push_back(m);
    return static_cast<int>(scene.materials.size() - 1);
}

Scene make_lit_sphere_on_floor() {
    Scene scene;
    const int mat = add_lambertian(scene, Spectrum(0.6f, 0.5f, 0.4f));
    add_instance(scene, add_sphere_object(scene, mat, 12, 24), Transform());
    const int floor = add_lambertian(scene, Spectrum(0.3f));
    add_instance(scene,
                 add_quad_object(scene, {-5, -1, 5}, {5, -1, 5}, {5, -1, -5}, {-5, -1, -5}, floor),
                 Transform());
    scene.lights.push_back(std::make_unique<PointLight>(Vec3(2, 3, 2), Spectrum(20)));
    return scene;
}

}  // namespace penumbra::test
