// What --views asks for: "orbit:N" (N views around the scene, core/camera/orbit_cameras.h)
// or a JSON file listing explicit cameras, each a position, a target and an up direction,
// or a camera-to-world matrix, with an optional vertical field of view.
#pragma once

#include <string>
#include <vector>

#include "core/camera/orbit_cameras.h"

namespace penumbra {

struct ExplicitView {
    std::string name;    // empty: view_name(index)
    Transform to_world;  // glTF camera axes: looks down local -Z, +Y up
    float yfov = 0;      // degrees; 0: the orbit settings' yfov
};

struct ViewList {
    int orbit = 0;                      // orbit:N; 0 when the views come from a file
    std::vector<ExplicitView> cameras;  // the file's
    size_t size() const { return orbit > 0 ? size_t(orbit) : cameras.size(); }
    std::string name(size_t i) const;
};

// The most views one --views gives: more is almost certainly a typo.
constexpr int kMaxViews = 100000;

// Checks the text as the command line takes it: "orbit:N" with N in [1, kMaxViews];
// other text names a file (read by read_views). Throws std::invalid_argument.
void check_views_spec(const std::string& spec);

// The views spec resolved: orbit:N, or the file read. Throws SceneError naming the file
// and the element ("cams.json: [2].look_at: expected 3 numbers").
ViewList read_views(const std::string& spec);
ViewList parse_views_json(const std::string& text, const std::string& path);

// Every view's camera, for a scene with these bounds rendered at aspect (width / height).
std::vector<CameraDesc> view_cameras(const ViewList& views, const Bounds3& bounds, float aspect,
                                     const OrbitSettings& settings);

}  // namespace penumbra
