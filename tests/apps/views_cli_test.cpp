// --views end to end: an orbit's transforms.json reprojects known points onto the pixels
// where the images show them, explicit cameras are rendered as given, every view of a
// scene comes from one load and equals a render of that view alone, and bad views specs
// and files fail before anything renders, naming the option or the file.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::run_penumbra;

struct Point {
    double x, y, z;
};
// The markers' centres: a red and a green emissive octahedron, nothing else in the scene.
const Point kRed = {0.6, 0.25, -0.3}, kGreen = {-0.5, -0.2, 0.45};

std::string write_marker_scene(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    const float r = 0.04f;
    const std::vector<float> pos = {r, 0, 0, -r, 0, 0, 0, r, 0, 0, -r, 0, 0, 0, r, 0, 0, -r};
    // Counter-clockwise seen from outside: (x, y, z) for faces whose signs multiply to +1.
    const std::vector<uint16_t> idx = {0, 2, 4, 1, 4, 2, 0, 5, 2, 1, 2, 5,
                                       0, 4, 3, 1, 3, 4, 0, 3, 5, 1, 5, 3};
    const int p = b.add(pos, test::kFloat, "VEC3");
    const int i = b.add(idx, test::kUShort, "SCALAR");
    auto mesh = [&](int material) {
        return "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(p) +
               "},\"indices\":" + std::to_string(i) + ",\"material\":" + std::to_string(material) +
               "}]}";
    };
    auto node = [](int mesh, const Point& t) {
        return "{\"mesh\":" + std::to_string(mesh) + ",\"translation\":[" + std::to_string(t.x) +
               "," + std::to_string(t.y) + "," + std::to_string(t.z) + "]}";
    };
    auto emissive = [](const char* rgb) {
        return std::string(
                   "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,0,1]},"
                   "\"emissiveFactor\":[") +
               rgb + "],\"doubleSided\":true}";
    };
    const std::string members = "\"materials\":[" + emissive("4,0,0") + "," + emissive("0,4,0") +
                                "],\"meshes\":[" + mesh(0) + "," + mesh(1) + "],\"nodes\":[" +
                                node(0, kRed) + "," + node(1, kGreen) +
                                "],\"scenes\":[{\"nodes\":[0,1]}],\"scene\":0";
    return b.write(dir, "markers.gltf", members, test::BufferStorage::DataUri);
}

json read_json(const std::string& path) {
    std::ifstream in(path);
    return json::parse(in);
}

// Where the camera of `frame` puts p, in pixels (x right, y down, pixel i spanning
// [i, i + 1)): through the transform's inverse into OpenGL camera axes (looking down -Z),
// then the pinhole of fl_x, fl_y, cx, cy.
std::pair<double, double> project(const json& t, const json& frame, const Point& p) {
    const json& m = frame.at("transform_matrix");
    double d[3] = {p.x - m[0][3].get<double>(), p.y - m[1][3].get<double>(),
                   p.z - m[2][3].get<double>()};
    double c[3];
    for (int k = 0; k < 3; ++k)  // R^T d: the rotation's columns are the camera's axes
        c[k] = m[0][k].get<double>() * d[0] + m[1][k].get<double>() * d[1] +
               m[2][k].get<double>() * d[2];
    EXPECT_LT(c[2], 0) << "the point is behind the camera";
    return {t.at("cx").get<double>() + t.at("fl_x").get<double>() * c[0] / -c[2],
            t.at("cy").get<double>() - t.at("fl_y").get<double>() * c[1] / -c[2]};
}

// The centroid of the pixels where `channel` (0 red, 1 green) exceeds the other.
std::pair<double, double> marker_centroid(const test::Pixels& px, int channel) {
    const size_t nc = px.channels.size();
    const int r = int(std::find(px.channels.begin(), px.channels.end(), "R") - px.channels.begin());
    const int g = int(std::find(px.channels.begin(), px.channels.end(), "G") - px.channels.begin());
    double sw = 0, sx = 0, sy = 0;
    for (int y = 0; y < px.height; ++y)
        for (int x = 0; x < px.width; ++x) {
            const float* v = &px.data[(size_t(y) * px.width + x) * nc];
            const double w = channel == 0 ? v[r] - v[g] : v[g] - v[r];
            if (w <= 0) continue;
            sw += w;
            sx += w * (x + 0.5);
            sy += w * (y + 0.5);
        }
    if (sw <= 0) return {-1e9, -1e9};
    return {sx / sw, sy / sw};
}

// The image `frame` names (in dir) shows each marker where the camera projects the
// marker's centre, within a pixel; `intrinsics` holds fl_x, fl_y, cx, cy, w and h. Returns
// the larger of the two distances.
double expect_frame_reprojects(const std::string& dir, const json& intrinsics, const json& frame) {
    const std::string image = dir + "/" + frame.at("file_path").get<std::string>();
    const test::Pixels px = test::read_pixels(image);
    EXPECT_TRUE(px.error.empty()) << px.error;
    EXPECT_EQ(px.width, intrinsics.at("w").get<int>());
    EXPECT_EQ(px.height, intrinsics.at("h").get<int>());
    const auto [rx, ry] = project(intrinsics, frame, kRed);
    const auto [gx, gy] = project(intrinsics, frame, kGreen);
    // The markers must not overlap, or the centroids would mix.
    EXPECT_GT(std::hypot(rx - gx, ry - gy), 10) << image;
    const auto [mrx, mry] = marker_centroid(px, 0);
    const auto [mgx, mgy] = marker_centroid(px, 1);
    const double er = std::hypot(mrx - rx, mry - ry), eg = std::hypot(mgx - gx, mgy - gy);
    EXPECT_LT(er, 1.0) << image << ": red at " << mrx << "," << mry << ", projected " << rx << ","
                       << ry;
    EXPECT_LT(eg, 1.0) << image << ": green at " << mgx << "," << mgy << ", projected " << gx << ","
                       << gy;
    return std::max(er, eg);
}

// A 96 x 96 render of the scene into out_dir with `more` options.
std::vector<std::string> render_args(const std::string& scene, const std::string& out_dir,
                                     std::vector<std::string> more, int spp = 16) {
    std::vector<std::string> a = {"render", scene,      "--out-dir", out_dir, "--width",
                                  "96",     "--height", "96",        "--spp", std::to_string(spp)};
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

TEST(ViewsCli, OrbitCamerasReprojectTheMarkersInEveryView) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    const auto r = run_penumbra(render_args(
        scene, dir.file("out"), {"--views", "orbit:8", "--orbit-elevation", "25", "--no-preview"}));
    ASSERT_EQ(r.status, 0) << r.output;
    const json t = read_json(dir.file("out/markers/transforms.json"));
    for (const char* key : {"camera_angle_x", "fl_x", "fl_y", "cx", "cy", "w", "h"})
        EXPECT_TRUE(t.contains(key)) << key;
    double worst = 0;
    for (const json& frame : t.at("frames"))
        worst = std::max(worst, expect_frame_reprojects(dir.file("out/markers"), t, frame));
    ASSERT_EQ(t.at("frames").size(), 8u);
    for (int v = 0; v < 8; ++v) {
        char name[16];
        std::snprintf(name, sizeof name, "%04d.exr", v);
        EXPECT_EQ(t["frames"][size_t(v)]["file_path"], name);
    }
    std::printf("largest marker reprojection error: %.3f px\n", worst);
    // One load and one accelerator build for the eight images.
    size_t loads = 0;
    for (size_t at = 0; (at = r.output.find("load and build:", at)) != std::string::npos; ++at)
        ++loads;
    EXPECT_EQ(loads, 1u) << r.output;
}

TEST(ViewsCli, OrbitViewsAreEvenlySpacedAtTheElevationAndTheJitterIsSeeded) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    auto centres = [&](const std::string& out, std::vector<std::string> more) {
        more.insert(more.end(), {"--views", "orbit:6", "--orbit-elevation", "30"});
        const auto r = run_penumbra(render_args(scene, dir.file(out), more, 1));
        EXPECT_EQ(r.status, 0) << r.output;
        std::vector<std::array<double, 3>> eyes;
        const json t = read_json(dir.file(out + "/markers/transforms.json"));
        for (const json& f : t.at("frames"))
            eyes.push_back({f["transform_matrix"][0][3].get<double>(),
                            f["transform_matrix"][1][3].get<double>(),
                            f["transform_matrix"][2][3].get<double>()});
        return eyes;
    };
    const auto eyes = centres("plain", {});
    const double cx = (kRed.x + kGreen.x) / 2, cy = (kRed.y + kGreen.y) / 2,
                 cz = (kRed.z + kGreen.z) / 2;
    for (size_t v = 0; v < eyes.size(); ++v) {
        const double dx = eyes[v][0] - cx, dy = eyes[v][1] - cy, dz = eyes[v][2] - cz;
        EXPECT_NEAR(std::atan2(dy, std::hypot(dx, dz)) * 180 / M_PI, 30, 1e-3) << v;
        // Azimuth 60 v degrees, from +Z towards +X.
        const double az = std::atan2(dx, dz) * 180 / M_PI;
        EXPECT_NEAR(std::remainder(az - 60.0 * double(v), 360.0), 0, 1e-3) << v;
    }
    const auto a = centres("a", {"--orbit-jitter", "10", "--orbit-seed", "3"});
    const auto b = centres("b", {"--orbit-jitter", "10", "--orbit-seed", "3"});
    const auto c = centres("c", {"--orbit-jitter", "10", "--orbit-seed", "4"});
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    EXPECT_NE(a, eyes);
}

TEST(ViewsCli, ExplicitCamerasAreRenderedAsGiven) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    // From the front by a matrix, from above (up -Z) with a narrower field, and named.
    dir.write("cams.json", R"([
        {"matrix": [[1,0,0,0.05],[0,1,0,0.02],[0,0,1,3],[0,0,0,1]]},
        {"name": "top", "position": [0.05, 3.5, 0.1], "look_at": [0.05, 0, 0.05],
         "up": [0, 0, -1], "yfov": 35},
        {"position": [2.5, 0.4, 1.0], "look_at": [0, 0, 0]}
    ])");
    const auto r = run_penumbra(
        render_args(scene, dir.file("out"),
                    {"--views", dir.file("cams.json"), "--name", "{camera}.exr", "--no-preview"}));
    ASSERT_EQ(r.status, 0) << r.output;
    const json t = read_json(dir.file("out/transforms.json"));
    ASSERT_EQ(t.at("frames").size(), 3u);
    EXPECT_EQ(t["frames"][0]["file_path"], "view_0000.exr");
    EXPECT_EQ(t["frames"][1]["file_path"], "top.exr");
    EXPECT_EQ(t["frames"][2]["file_path"], "view_0002.exr");
    // The intrinsics differ (35 degrees against the default 40): given per frame.
    EXPECT_FALSE(t.contains("fl_x"));
    EXPECT_NE(t["frames"][0]["fl_y"], t["frames"][1]["fl_y"]);
    const json m0 = json::array({json::array({1, 0, 0, 0.05f}), json::array({0, 1, 0, 0.02f}),
                                 json::array({0, 0, 1, 3}), json::array({0, 0, 0, 1})});
    EXPECT_EQ(t["frames"][0]["transform_matrix"], m0);
    EXPECT_NEAR(t["frames"][1]["transform_matrix"][1][3].get<double>(), 3.5, 1e-6);
    // Per-frame intrinsics: each frame reprojects with its own.
    for (const json& frame : t["frames"]) expect_frame_reprojects(dir.file("out"), frame, frame);
}

// A grey box from kBoxLo to kBoxHi, nothing else.
const Point kBoxLo = {-0.3, 0.1, -0.5}, kBoxHi = {0.5, 0.6, 0.2};

std::string write_box_scene(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    std::vector<float> pos;
    for (int c = 0; c < 8; ++c) {
        pos.push_back(float(c & 1 ? kBoxHi.x : kBoxLo.x));
        pos.push_back(float(c & 2 ? kBoxHi.y : kBoxLo.y));
        pos.push_back(float(c & 4 ? kBoxHi.z : kBoxLo.z));
    }
    // Two triangles per face, counter-clockwise seen from outside.
    const std::vector<uint16_t> idx = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                       2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    const int p = b.add(pos, test::kFloat, "VEC3");
    const int i = b.add(idx, test::kUShort, "SCALAR");
    const std::string members =
        "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.5,0.5,1]}}]," +
        test::one_mesh_scene("{\"attributes\":{\"POSITION\":" + std::to_string(p) +
                             "},\"indices\":" + std::to_string(i) + ",\"material\":0}");
    return b.write(dir, "box.gltf", members, test::BufferStorage::DataUri);
}

// The box's silhouette is the convex hull of its projected corners, so the pixels its
// depth covers span the hull's extent, within a pixel, in every view of the orbit.
TEST(ViewsCli, TheBoxCoversItsCornersProjectedExtentInEveryView) {
    const test::ScratchDir dir;
    const std::string scene = write_box_scene(dir);
    const auto r = run_penumbra({"render",
                                 scene,
                                 "--out-dir",
                                 dir.file("out"),
                                 "--width",
                                 "96",
                                 "--height",
                                 "72",
                                 "--spp",
                                 "4",
                                 "--filter",
                                 "box",
                                 "--aov",
                                 "depth",
                                 "--views",
                                 "orbit:8",
                                 "--orbit-elevation",
                                 "25",
                                 "--no-preview",
                                 "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    const json t = read_json(dir.file("out/box/transforms.json"));
    ASSERT_EQ(t.at("frames").size(), 8u);
    double worst = 0;
    for (const json& frame : t["frames"]) {
        const std::string image = dir.file("out/box/" + frame["file_path"].get<std::string>());
        double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
        for (int c = 0; c < 8; ++c) {
            const Point corner = {c & 1 ? kBoxHi.x : kBoxLo.x, c & 2 ? kBoxHi.y : kBoxLo.y,
                                  c & 4 ? kBoxHi.z : kBoxLo.z};
            const auto [x, y] = project(t, frame, corner);
            lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
            lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
        }
        const test::Pixels px = test::read_pixels(image);
        ASSERT_TRUE(px.error.empty()) << px.error;
        const size_t z = size_t(std::find(px.channels.begin(), px.channels.end(), "Depth.Z") -
                                px.channels.begin());
        ASSERT_LT(z, px.channels.size());
        double mlo[2] = {1e9, 1e9}, mhi[2] = {-1e9, -1e9};
        for (int y = 0; y < px.height; ++y)
            for (int x = 0; x < px.width; ++x)
                if (px.data[(size_t(y) * px.width + x) * px.channels.size() + z] < 1e9f) {
                    mlo[0] = std::min(mlo[0], double(x)), mhi[0] = std::max(mhi[0], x + 1.0);
                    mlo[1] = std::min(mlo[1], double(y)), mhi[1] = std::max(mhi[1], y + 1.0);
                }
        for (int a = 0; a < 2; ++a) {
            EXPECT_GT(lo[a], 0) << image << ": the box leaves the frame";
            EXPECT_LT(hi[a], a == 0 ? 96 : 72) << image << ": the box leaves the frame";
            EXPECT_NEAR(mlo[a], lo[a], 1.0) << image << " axis " << a;
            EXPECT_NEAR(mhi[a], hi[a], 1.0) << image << " axis " << a;
            worst = std::max({worst, std::abs(mlo[a] - lo[a]), std::abs(mhi[a] - hi[a])});
        }
    }
    std::printf("largest difference of the box's extent: %.3f px\n", worst);
}

// With frames, every image shares one load of the file, and each frame's views one pose
// and accelerator build; transforms.json lists every image.
TEST(ViewsCli, FramesTimesViewsLoadOnceAndPoseOncePerFrame) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    const auto r = run_penumbra(
        render_args(scene, dir.file("out"), {"--views", "orbit:3", "--frames", "1-2"}, 1));
    ASSERT_EQ(r.status, 0) << r.output;
    auto count = [&r](const std::string& what) {
        size_t n = 0;
        for (size_t at = 0; (at = r.output.find(what, at)) != std::string::npos; ++at) ++n;
        return n;
    };
    EXPECT_EQ(count("load and build:"), 1u);
    EXPECT_EQ(count("pose and build:"), 1u);
    const json t = read_json(dir.file("out/markers/transforms.json"));
    ASSERT_EQ(t.at("frames").size(), 6u);
    EXPECT_EQ(t["frames"][0]["file_path"], "0000_0001.png");
    EXPECT_EQ(t["frames"][5]["file_path"], "0002_0002.png");
    std::unique_ptr<OIIO::ImageInput> in =
        OIIO::ImageInput::open(dir.file("out/markers/0002_0001.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("penumbra:view"), "view_0002");
    EXPECT_EQ(in->spec().get_string_attribute("penumbra:views"), "orbit:3");
}

// Only the camera changes between the views of one load: a view rendered among the
// orbit's is bitwise the image of its camera rendered from a load of its own.
TEST(ViewsCli, EachViewEqualsARenderOfItsCameraAlone) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    auto r = run_penumbra(
        render_args(scene, dir.file("orbit"), {"--views", "orbit:4", "--no-preview"}, 4));
    ASSERT_EQ(r.status, 0) << r.output;
    const json t = read_json(dir.file("orbit/markers/transforms.json"));
    const json view2 = t["frames"][2];
    std::ofstream(dir.file("one.json"))
        << json::array({{{"matrix", view2["transform_matrix"]}}}).dump();
    r = run_penumbra(render_args(scene, dir.file("alone"),
                                 {"--views", dir.file("one.json"), "--no-preview"}, 4));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(
        test::same_pixels(dir.file("orbit/markers/0002.exr"), dir.file("alone/markers/0000.exr")));
}

// A job file's "views" takes orbit:N as it is and a cameras file relative to the job
// file; the previews are what transforms.json names.
TEST(ViewsCli, JobFilesTakeViews) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    fs::create_directories(dir.file("jobs"));
    dir.write("jobs/cams.json", R"([{"position": [0, 0.5, 3], "look_at": [0, 0, 0]}])");
    dir.write("jobs/job.json", R"({"defaults": {"width": 48, "height": 48, "spp": 2},
        "jobs": [{"scene": "../markers.gltf", "views": "orbit:2", "output": "orbit/{view}.exr"},
                 {"scene": "../markers.gltf", "views": "cams.json", "output": "cams/{view}.exr"}]})");
    const auto r = run_penumbra({"render", "--job", dir.file("jobs/job.json")});
    ASSERT_EQ(r.status, 0) << r.output;
    const json orbit = read_json(dir.file("jobs/orbit/transforms.json"));
    ASSERT_EQ(orbit["frames"].size(), 2u);
    EXPECT_EQ(orbit["frames"][1]["file_path"], "0001.png");
    EXPECT_TRUE(fs::exists(dir.file("jobs/orbit/0001.png")));
    EXPECT_TRUE(fs::exists(dir.file("jobs/orbit/0001.exr")));
    const json cams = read_json(dir.file("jobs/cams/transforms.json"));
    ASSERT_EQ(cams["frames"].size(), 1u);
    EXPECT_NEAR(cams["frames"][0]["transform_matrix"][2][3].get<double>(), 3, 1e-6);
}

// A rerun skips the finished views and still lists them; a view rendered again replaces
// its own entry.
TEST(ViewsCli, ResumedBatchesKeepEveryViewInTransformsJson) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    const std::vector<std::string> args =
        render_args(scene, dir.file("out"), {"--views", "orbit:3", "-q"}, 1);
    ASSERT_EQ(run_penumbra(args).status, 0);
    fs::remove(dir.file("out/markers/0001.exr"));
    fs::remove(dir.file("out/markers/0001.png"));
    const std::string before = [&] {
        std::ifstream in(dir.file("out/markers/transforms.json"));
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    ASSERT_EQ(run_penumbra(args).status, 0);
    std::ifstream in(dir.file("out/markers/transforms.json"));
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), before);
}

// On the farm, tasks of two views each render the orbit's images as `render --job` does,
// and the tasks, run at once, each add their views to one transforms.json.
TEST(ViewsCli, FarmTasksShareTransformsJson) {
    const test::ScratchDir dir;
    write_marker_scene(dir);
    auto job = [&](const std::string& name, const std::string& out) {
        return dir.write(name, R"({"defaults": {"width": 32, "height": 32, "spp": 2},
            "jobs": [{"scene": "markers.gltf", "views": "orbit:4", "frames_per_task": 2,
                      "output": ")" +
                                   out + R"(/{view}.exr"}]})");
    };
    const std::string ref_job = job("ref.json", "ref"), farm_job = job("farm.json", "farm");
    ASSERT_EQ(run_penumbra({"render", "--job", ref_job, "-q"}).status, 0);
    {
        test::CliProcess a({"farm", "task", farm_job, "--index", "0"});
        test::CliProcess b({"farm", "task", farm_job, "--index", "1"});
        const test::CliResult ra = a.wait(), rb = b.wait();
        ASSERT_EQ(ra.status, 0) << ra.output;
        ASSERT_EQ(rb.status, 0) << rb.output;
    }
    const json t = read_json(dir.file("farm/transforms.json"));
    ASSERT_EQ(t.at("frames").size(), 4u);
    std::set<std::string> files;
    for (const json& f : t["frames"]) files.insert(f["file_path"].get<std::string>());
    EXPECT_EQ(files, (std::set<std::string>{"0000.png", "0001.png", "0002.png", "0003.png"}));
    const json ref = read_json(dir.file("ref/transforms.json"));
    for (const json& f : ref["frames"]) {
        const std::string name = f["file_path"].get<std::string>();
        for (const json& g : t["frames"])
            if (g["file_path"] == name) EXPECT_EQ(g["transform_matrix"], f["transform_matrix"]);
        const std::string exr = name.substr(0, 4) + ".exr";
        EXPECT_TRUE(test::same_pixels(dir.file("ref/" + exr), dir.file("farm/" + exr))) << exr;
    }
}

TEST(ViewsCli, BadViewsFailBeforeRenderingNamingTheOptionOrFile) {
    const test::ScratchDir dir;
    const std::string scene = write_marker_scene(dir);
    dir.write("broken.json", "[{\"position\": [0, 0, 3], \"look_at\": [0, 0, 0]},");
    dir.write("short.json", R"([{"position": [0, 0, 3], "look_at": [0, 0]}])");
    dir.write("lonely.json", R"([{"position": [0, 0, 3]}])");
    dir.write("scaled.json", R"([{"matrix": [[2,0,0,0],[0,2,0,0],[0,0,2,3],[0,0,0,1]]}])");
    dir.write("typo.json", R"([{"position": [0, 0, 3], "lookat": [0, 0, 0]}])");
    dir.write("fov.json", R"([{"position": [0, 0, 3], "look_at": [0, 0, 0], "yfov": 0.7}, )"
                          R"({"position": [0, 0, 3], "look_at": [0, 0, 0], "yfov": 180}])");
    dir.write("empty.json", "[]");
    dir.write("job.json", R"({"jobs": [{"scene": "markers.gltf", "views": "orbit:x"}]})");
    struct Case {
        std::vector<std::string> args;
        std::string message;
    } cases[] = {
        {{"--views", "orbit:0"}, "--views: views 'orbit:0': expected orbit:N with N from 1"},
        {{"--views", "orbit:"}, "--views: views 'orbit:': expected orbit:N"},
        {{"--views", "orbit:8x"}, "--views: views 'orbit:8x': expected orbit:N"},
        {{"--views", dir.file("none.json")},
         dir.file("none.json") + ": cannot open the views file"},
        {{"--views", dir.file("broken.json")}, dir.file("broken.json") + ": not valid JSON"},
        {{"--views", dir.file("short.json")},
         dir.file("short.json") + ": [0].look_at: expected 3 numbers"},
        {{"--views", dir.file("lonely.json")},
         dir.file("lonely.json") + ": [0]: position and look_at go together"},
        {{"--views", dir.file("scaled.json")},
         dir.file("scaled.json") + ": [0].matrix: the upper 3x3 is not a rotation"},
        {{"--views", dir.file("typo.json")}, dir.file("typo.json") + ": [0].lookat: unknown key"},
        {{"--views", dir.file("fov.json")},
         dir.file("fov.json") + ": [1].yfov: expected degrees between 0 and 180"},
        {{"--views", dir.file("empty.json")},
         dir.file("empty.json") + ": expected a non-empty JSON array"},
        {{"--views", "orbit:3", "--name", "same.exr"},
         "3 views would all write 'same.exr'; add {view}"},
        {{"--views", "orbit:3", "--camera", "0"}, "the views replace the file's camera"},
        {{"--job", dir.file("job.json")},
         dir.file("job.json") + ": jobs[0].views: views 'orbit:x'"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = {"render", "--out-dir", dir.file("out"), "--spp", "1"};
        if (c.args[0] != "--job") args.insert(args.begin() + 1, scene);
        args.insert(args.end(), c.args.begin(), c.args.end());
        const auto r = run_penumbra(args);
        EXPECT_NE(r.status, 0) << c.message;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.message << "\n" << r.output;
        EXPECT_FALSE(fs::exists(dir.file("out"))) << c.message;
    }
}

}  // namespace
}  // namespace penumbra
