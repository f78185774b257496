// The timeline options to a shutter interval: each form, the default, and every
// conflict or invalid value rejected with a message naming the options.
#include "job/timeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace penumbra {
namespace {

std::string error_of(const TimelineSettings& t) {
    try {
        resolve_shutter(t);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "<no error>";
}

TEST(Timeline, DefaultIsAStillAtTimeZero) {
    const ShutterInterval s = resolve_shutter({});
    EXPECT_EQ(s.open, 0);
    EXPECT_EQ(s.close, 0);
}

TEST(Timeline, EachFormGivesItsInterval) {
    TimelineSettings t;
    t.time = 1.5;
    EXPECT_EQ(resolve_shutter(t).open, 1.5);
    EXPECT_EQ(resolve_shutter(t).close, 1.5);

    t = {};
    t.shutter_open = 0.25;
    t.shutter_close = 0.75;
    EXPECT_EQ(resolve_shutter(t).open, 0.25);
    EXPECT_EQ(resolve_shutter(t).close, 0.75);

    // Frame 12 at 24 fps with a 180-degree shutter: open at 0.5 s for half a frame.
    t = {};
    t.frame = 12;
    t.fps = 24;
    t.shutter = 0.5;
    EXPECT_DOUBLE_EQ(resolve_shutter(t).open, 0.5);
    EXPECT_DOUBLE_EQ(resolve_shutter(t).close, 0.5 + 0.5 / 24);
    // Without --shutter a frame is a still at its time.
    t.shutter.reset();
    t.fps = 10;
    EXPECT_DOUBLE_EQ(resolve_shutter(t).open, 1.2);
    EXPECT_DOUBLE_EQ(resolve_shutter(t).close, 1.2);
}

TEST(Timeline, ConflictsAndInvalidValuesAreRejected) {
    TimelineSettings t;
    t.time = 1;
    t.shutter_open = 0;
    t.shutter_close = 1;
    EXPECT_NE(error_of(t).find("--time (an instant) conflicts with --shutter-open"),
              std::string::npos);
    t = {};
    t.shutter_open = 0;
    EXPECT_NE(error_of(t).find("must be given together"), std::string::npos);
    t.shutter_close = -1;
    EXPECT_NE(error_of(t).find("--shutter-close -1.000000 is before --shutter-open 0.000000"),
              std::string::npos);
    t = {};
    t.frame = 3;
    t.time = 2;
    EXPECT_NE(error_of(t).find("--frame conflicts with --time"), std::string::npos);
    t = {};
    t.shutter = 0.5;
    EXPECT_NE(error_of(t).find("needs --frame or --frames"), std::string::npos);
    t.frame = 1;
    t.shutter = 1.5;
    EXPECT_NE(error_of(t).find("is not a fraction of a frame"), std::string::npos);
    t.shutter = 0.5;
    t.fps = 0;
    EXPECT_NE(error_of(t).find("--fps must be a positive number"), std::string::npos);
    t = {};
    t.time = std::nan("");
    EXPECT_NE(error_of(t).find("--time must be a finite number"), std::string::npos);
}

}  // namespace
}  // namespace penumbra
