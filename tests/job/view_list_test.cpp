#include "job/view_list.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/error.h"

namespace penumbra {
namespace {

TEST(ViewList, OrbitSpecs) {
    EXPECT_NO_THROW(check_views_spec("orbit:1"));
    EXPECT_NO_THROW(check_views_spec("orbit:100000"));
    EXPECT_NO_THROW(check_views_spec("cams.json"));  // a file, read later
    for (const char* bad : {"orbit:", "orbit:0", "orbit:-2", "orbit:1.5", "orbit:100001",
                            "orbit: 3", "orbit:99999999999"})
        EXPECT_THROW(check_views_spec(bad), std::invalid_argument) << bad;
    const ViewList v = read_views("orbit:12");
    EXPECT_EQ(v.size(), 12u);
    EXPECT_EQ(v.name(3), "view_0003");
}

TEST(ViewList, CamerasFromPositionsAndMatrices) {
    const ViewList v = parse_views_json(R"([
        {"position": [0, 1, 4], "look_at": [0, 1, 0], "yfov": 30, "name": "front"},
        {"transform_matrix": [[0,0,1,5],[0,1,0,1],[-1,0,0,0],[0,0,0,1]]}
    ])",
                                        "cams.json");
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(v.name(0), "front");
    EXPECT_EQ(v.name(1), "view_0001");
    EXPECT_EQ(v.cameras[0].yfov, 30);
    EXPECT_EQ(v.cameras[1].yfov, 0);  // the settings' default
    // Both look at the point (0, 1, 0): the first along -Z, the second along -X.
    const Vec3 f0 = v.cameras[0].to_world.vector(Vec3(0, 0, -1));
    const Vec3 f1 = v.cameras[1].to_world.vector(Vec3(0, 0, -1));
    EXPECT_NEAR(f0.z, -1, 1e-6);
    EXPECT_NEAR(f1.x, -1, 1e-6);
    EXPECT_EQ(v.cameras[1].to_world.point(Vec3(0, 0, 0)), Vec3(5, 1, 0));
    OrbitSettings s;
    s.yfov = 50;
    const std::vector<CameraDesc> cams = view_cameras(v, Bounds3{Vec3(-1), Vec3(1)}, 1.5f, s);
    EXPECT_NEAR(cams[0].yfov, 30 * kPi / 180, 1e-6);
    EXPECT_NEAR(cams[1].yfov, 50 * kPi / 180, 1e-6);
    EXPECT_EQ(cams[1].name, "view_0001");
}

TEST(ViewList, ErrorsNameTheFileAndTheElement) {
    struct Case {
        const char* json;
        const char* message;
    } cases[] = {
        {"{}", "v.json: expected a non-empty JSON array of cameras"},
        {"[3]", "v.json: [0]: expected an object"},
        {R"([{"look_at": [0,0,0]}])", "v.json: [0]: position and look_at go together"},
        {R"([{"position": [0,0,1], "look_at": [0,0,1]}])", "v.json: [0]: look_at equals position"},
        {R"([{"position": [0,0,1], "look_at": [0,0,0], "up": [0,0,2]}])",
         "v.json: [0].up: is zero or parallel to the viewing direction"},
        {R"([{"position": [0,0,"1"], "look_at": [0,0,0]}])",
         "v.json: [0].position: expected 3 numbers"},
        {R"([{"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]}])", "v.json: [0].matrix: expected 4 rows"},
        {R"([{"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,1,1]]}])",
         "v.json: [0].matrix: expected 4 rows"},
        {R"([{"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "position": [0,0,1], "look_at": [0,0,0]}])",
         "v.json: [0]: expected either position and look_at (and up), or matrix"},
        {R"([{"position": [0,0,1], "look_at": [0,0,0], "yfov": -3}])",
         "v.json: [0].yfov: expected degrees"},
        {R"([{"position": [0,0,1], "look_at": [0,0,0], "name": 7}])",
         "v.json: [0].name: expected a string"},
    };
    for (const Case& c : cases) {
        try {
            parse_views_json(c.json, "v.json");
            ADD_FAILURE() << "accepted " << c.json;
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos)
                << e.what() << "\nexpected: " << c.message;
        }
    }
}

}  // namespace
}  // namespace penumbra
