#include "job/view_list.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "core/error.h"

namespace penumbra {

using nlohmann::json;

namespace {

constexpr const char* kOrbit = "orbit:";

bool is_orbit(const std::string& spec) { return spec.rfind(kOrbit, 0) == 0; }

int orbit_count(const std::string& spec) {
    const std::string n = spec.substr(std::string(kOrbit).size());
    const std::string why = "views '" + spec + "': expected orbit:N with N from 1 to " +
                            std::to_string(kMaxViews) + ", or a cameras JSON file";
    if (n.empty() || n.size() > 6 || n.find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument(why);
    const int count = std::stoi(n);
    if (count < 1 || count > kMaxViews) throw std::invalid_argument(why);
    return count;
}

Vec3 vec3(const json& v, const std::string& where) {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number())
        throw SceneError(where + ": expected 3 numbers");
    const Vec3 r(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
    if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z))
        throw SceneError(where + ": expected finite numbers");
    return r;
}

// A camera-to-world matrix as rows (transforms.json's layout): a rotation and a
// translation, since a scaled or sheared camera has no field of view of its own.
Transform rigid_matrix(const json& v, const std::string& where) {
    const std::string expected = where +
                                 ": expected 4 rows of 4 numbers, a rotation and a "
                                 "translation with last row [0, 0, 0, 1]";
    if (!v.is_array() || v.size() != 4) throw SceneError(expected);
    Mat4 m;
    for (int r = 0; r < 4; ++r) {
        const json& row = v[size_t(r)];
        if (!row.is_array() || row.size() != 4) throw SceneError(expected);
        for (int c = 0; c < 4; ++c) {
            if (!row[size_t(c)].is_number()) throw SceneError(expected);
            m.m[r][c] = row[size_t(c)].get<float>();
            if (!std::isfinite(m.m[r][c])) throw SceneError(expected);
        }
    }
    if (m.m[3][0] != 0 || m.m[3][1] != 0 || m.m[3][2] != 0 || m.m[3][3] != 1)
        throw SceneError(expected);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            float dot = 0;
            for (int r = 0; r < 3; ++r) dot += m.m[r][a] * m.m[r][b];
            if (std::abs(dot - (a == b ? 1.0f : 0.0f)) > 1e-3f)
                throw SceneError(where +
                                 ": the upper 3x3 is not a rotation (its columns must "
                                 "be orthonormal)");
        }
    return Transform(m);
}

ExplicitView read_view(const json& v, const std::string& where) {
    if (!v.is_object()) throw SceneError(where + ": expected an object");
    for (const auto& [key, value] : v.items())
        if (key != "name" && key != "position" && key != "look_at" && key != "up" &&
            key != "yfov" && key != "matrix" && key != "transform_matrix")
            throw SceneError(where + "." + key +
                             ": unknown key (expected name, position, look_at, up, yfov, "
                             "matrix or transform_matrix)");
    ExplicitView view;
    if (v.contains("name")) {
        if (!v["name"].is_string()) throw SceneError(where + ".name: expected a string");
        view.name = v["name"].get<std::string>();
    }
    const char* matrix_key = v.contains("matrix") ? "matrix" : "transform_matrix";
    const bool has_matrix = v.contains(matrix_key);
    const bool has_look = v.contains("position") || v.contains("look_at");
    if (has_matrix == has_look || (v.contains("matrix") && v.contains("transform_matrix")))
        throw SceneError(where + ": expected either position and look_at (and up), or matrix");
    if (has_matrix) {
        view.to_world = rigid_matrix(v[matrix_key], where + "." + matrix_key);
    } else {
        if (!v.contains("position") || !v.contains("look_at"))
            throw SceneError(where + ": position and look_at go together");
        const Vec3 eye = vec3(v["position"], where + ".position");
        const Vec3 target = vec3(v["look_at"], where + ".look_at");
        const Vec3 up = v.contains("up") ? vec3(v["up"], where + ".up") : Vec3(0, 1, 0);
        if (length(target - eye) <= 0) throw SceneError(where + ": look_at equals position");
        if (length(cross(up, target - eye)) <= 1e-6f * length(up) * length(target - eye))
            throw SceneError(where + ".up: is zero or parallel to the viewing direction");
        view.to_world = Transform::look_at(eye, target, up);
    }
    if (v.contains("yfov")) {
        const json& y = v["yfov"];
        if (!y.is_number() || !(y.get<double>() > 0 && y.get<double>() < 180))
            throw SceneError(where + ".yfov: expected degrees between 0 and 180");
        view.yfov = y.get<float>();
    }
    return view;
}

}  // namespace

std::string ViewList::name(size_t i) const {
    if (orbit == 0 && !cameras[i].name.empty()) return cameras[i].name;
    return view_name(i);
}

void check_views_spec(const std::string& spec) {
    if (spec.empty()) return;
    if (is_orbit(spec)) orbit_count(spec);
}

ViewList parse_views_json(const std::string& text, const std::string& path) {
    json root;
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        throw SceneError(path + ": not valid JSON: " + e.what());
    }
    if (!root.is_array() || root.empty())
        throw SceneError(path + ": expected a non-empty JSON array of cameras");
    if (root.size() > size_t(kMaxViews))
        throw SceneError(path + ": more than " + std::to_string(kMaxViews) + " cameras");
    ViewList list;
    for (size_t i = 0; i < root.size(); ++i)
        list.cameras.push_back(read_view(root[i], path + ": [" + std::to_string(i) + "]"));
    return list;
}

ViewList read_views(const std::string& spec) {
    if (is_orbit(spec)) {
        ViewList list;
        try {
            list.orbit = orbit_count(spec);
        } catch (const std::invalid_argument& e) {
            throw SceneError(std::string("--views: ") + e.what());
        }
        return list;
    }
    std::ifstream in(spec, std::ios::binary);
    if (!in)
        throw SceneError(spec +
                         ": cannot open the views file (--views takes orbit:N or a "
                         "cameras JSON file)");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_views_json(text.str(), spec);
}

std::vector<CameraDesc> view_cameras(const ViewList& views, const Bounds3& bounds, float aspect,
                                     const OrbitSettings& settings) {
    if (views.orbit > 0) return orbit_cameras(bounds, aspect, views.orbit, settings);
    std::vector<CameraDesc> cams;
    for (size_t i = 0; i < views.cameras.size(); ++i) {
        const ExplicitView& v = views.cameras[i];
        cams.push_back(placed_camera(views.name(i), v.to_world, v.yfov > 0 ? v.yfov : settings.yfov,
                                     aspect, bounds));
    }
    return cams;
}

}  // namespace penumbra
