// Output name templates and the "is this output finished" test behind batch resume.
#include "job/render_output.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <fstream>

#include "io/image/image_writer.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

TEST(RenderOutput, ExpandsPlaceholders) {
    const OutputNameFields f{"cornell-box", "front", 7, 3};
    EXPECT_EQ(expand_output_name("{scene}_{camera}.exr", f), "cornell-box_front.exr");
    EXPECT_EQ(expand_output_name("{scene}/{frame}.exr", f), "cornell-box/0007.exr");
    EXPECT_EQ(expand_output_name("{index}-{scene}-{frame}-{index}", f),
              "3-cornell-box-0007-3");
    EXPECT_EQ(expand_output_name("out.exr", f), "out.exr");
    EXPECT_EQ(expand_output_name("{scene}/{view}_{frame}.exr", {"s", "c", 2, 0, 41}),
              "s/0041_0002.exr");
    EXPECT_EQ(expand_output_name("{frame}", {"s", "c", 12345, 0}), "12345");
    // Names from the file cannot escape the folder or hide control characters.
    EXPECT_EQ(expand_output_name("{camera}.exr", {"s", "../up\tcam", 0, 0}), ".._up_cam.exr");
    EXPECT_EQ(expand_output_name("{camera}.exr", {"s", "", 0, 0}), "camera.exr");
    EXPECT_THROW(expand_output_name("{shot}.exr", f), std::invalid_argument);
    EXPECT_THROW(expand_output_name("{scene.exr", f), std::invalid_argument);
    EXPECT_TRUE(uses_placeholder("{scene}_{camera}.exr", "camera"));
    EXPECT_FALSE(uses_placeholder("{scene}.exr", "camera"));
}

TEST(RenderOutput, OnlyACompleteNonPartialImageIsFinished) {
    const test::ScratchDir dir;
    const Image img(2, 2, 3);
    write_exr(dir.file("done.exr"), img, {{"penumbra:partial", std::string("0")}});
    write_exr(dir.file("partial.exr"), img, {{"penumbra:partial", std::string("1")}});
    write_exr(dir.file("other.exr"), img, {});
    dir.write("garbage.exr", "not an image");
    EXPECT_TRUE(is_finished_render(dir.file("done.exr")));
    EXPECT_TRUE(is_finished_render(dir.file("other.exr")));
    EXPECT_FALSE(is_finished_render(dir.file("partial.exr")));
    EXPECT_FALSE(is_finished_render(dir.file("garbage.exr")));
    EXPECT_FALSE(is_finished_render(dir.file("missing.exr")));
}

}  // namespace
}  // namespace penumbra
