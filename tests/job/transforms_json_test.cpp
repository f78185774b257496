#include "job/transforms_json.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using nlohmann::json;

TransformsFrame frame(const std::string& file, float x, const Intrinsics& k) {
    TransformsFrame f;
    f.file_path = file;
    f.transform_matrix = Transform::translate(Vec3(x, 1, 2)).matrix();
    f.intrinsics = k;
    return f;
}

// A 40-degree vertical field on 200 x 100: fl = 50 / tan 20 degrees, the principal point
// the centre, and camera_angle_x the horizontal field that square pixels give.
TEST(TransformsJson, IntrinsicsOfAPerspectiveCamera) {
    const Intrinsics k = perspective_intrinsics(200, 100, 40 * kPi / 180);
    EXPECT_NEAR(k.fl_y, 50 / std::tan(20 * M_PI / 180), 1e-4);
    EXPECT_EQ(k.fl_x, k.fl_y);
    EXPECT_EQ(k.cx, 100);
    EXPECT_EQ(k.cy, 50);
    const json j = json::parse(transforms_json_text({frame("a.png", 0, k)}));
    EXPECT_NEAR(j["camera_angle_x"].get<double>(), 2 * std::atan(100 / k.fl_x), 1e-12);
    EXPECT_NEAR(j["camera_angle_y"].get<double>(), 40 * M_PI / 180, 1e-6);
    EXPECT_EQ(j["w"], 200);
    EXPECT_EQ(j["h"], 100);
    EXPECT_EQ(j["camera_model"], "OPENCV");
    EXPECT_EQ(j["frames"][0]["file_path"], "a.png");
    EXPECT_EQ(j["frames"][0]["transform_matrix"],
              json::parse("[[1,0,0,0],[0,1,0,1],[0,0,1,2],[0,0,0,1]]"));
    EXPECT_FALSE(j["frames"][0].contains("fl_x"));  // shared: at the top only
}

TEST(TransformsJson, DifferentIntrinsicsGoInEachFrame) {
    const Intrinsics a = perspective_intrinsics(64, 64, 0.7f),
                     b = perspective_intrinsics(64, 64, 0.5f);
    const json j = json::parse(transforms_json_text({frame("a.png", 0, a), frame("b.png", 1, b)}));
    EXPECT_FALSE(j.contains("fl_x"));
    EXPECT_EQ(j["frames"][0]["fl_x"], a.fl_x);
    EXPECT_EQ(j["frames"][1]["fl_x"], b.fl_x);
}

// An update keeps the frames it does not rewrite, replaces those of the same file and
// appends the new ones, and reads back what it wrote.
TEST(TransformsJson, UpdatesMergeByFilePath) {
    const test::ScratchDir dir;
    const std::string path = dir.file("transforms.json");
    const Intrinsics k = perspective_intrinsics(32, 24, 0.7f);
    update_transforms_json(path, {frame("0.png", 0, k), frame("1.png", 1, k)});
    update_transforms_json(path, {frame("1.png", 5, k), frame("2.png", 2, k)});
    const std::vector<TransformsFrame> read = read_transforms_json(path);
    ASSERT_EQ(read.size(), 3u);
    EXPECT_EQ(read[0].file_path, "0.png");
    EXPECT_EQ(read[1].file_path, "1.png");
    EXPECT_EQ(read[1].transform_matrix.m[0][3], 5);
    EXPECT_EQ(read[2].file_path, "2.png");
    EXPECT_TRUE(read[2].intrinsics == k);
    dir.write("broken.json", "{\"frames\": [");
    EXPECT_TRUE(read_transforms_json(dir.file("broken.json")).empty());
}

// Farm tasks update one file from several processes: the folder lock keeps every update
// (separate opens of the folder exclude each other, across threads as across processes).
TEST(TransformsJson, ConcurrentUpdatesLoseNothing) {
    const test::ScratchDir dir;
    const std::string path = dir.file("views/transforms.json");
    const Intrinsics k = perspective_intrinsics(16, 16, 0.7f);
    std::vector<std::thread> writers;
    std::atomic<int> failed{0};
    for (int w = 0; w < 6; ++w)
        writers.emplace_back([&, w] {
            for (int i = 0; i < 15; ++i) {
                const std::string name = std::to_string(w) + "_" + std::to_string(i) + ".png";
                try {
                    update_transforms_json(path, {frame(name, 0, k)});
                } catch (const std::exception&) {
                    ++failed;
                }
            }
        });
    for (std::thread& t : writers) t.join();
    EXPECT_EQ(failed, 0);
    EXPECT_EQ(read_transforms_json(path).size(), 90u);
}

}  // namespace
}  // namespace penumbra
