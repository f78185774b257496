// The batch progress line: images done, the overall fraction including the current
// image, and formatting helpers.
#include "core/progress.h"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

TEST(Progress, BatchLineCountsFinishedImagesAndTheCurrentOne) {
    BatchProgress batch(4, true);
    EXPECT_NE(batch.describe(0.0, 0, 0, false).find("0 of 4 images done, 0.0%"),
              std::string::npos);
    batch.job_finished(1000);
    batch.job_finished(0);  // failed and skipped images count as done too
    EXPECT_EQ(batch.jobs_done(), 2u);
    // Two of four done and half of the third: 62.5%.
    EXPECT_NE(batch.describe(0.5, 0, 0, false).find("2 of 4 images done, 62.5%"),
              std::string::npos)
        << batch.describe(0.5, 0, 0, false);
    // On a terminal: a bar that names the image being rendered (the third).
    const std::string bar = batch.describe(0.5, 0, 0, true);
    EXPECT_EQ(bar.rfind("batch 3/4 [", 0), 0u) << bar;
    EXPECT_NE(bar.find("62.5%"), std::string::npos) << bar;
}

TEST(Progress, Formatting) {
    EXPECT_EQ(format_count(999), "999");
    EXPECT_EQ(format_count(1500), "1.5k");
    EXPECT_EQ(format_count(2.5e6), "2.50M");
    EXPECT_EQ(format_count(3e9), "3.00G");
    EXPECT_EQ(format_duration(1.5), "1.50s");
    EXPECT_EQ(format_duration(75), "1m 15s");
    EXPECT_GE(process_cpu_seconds(), 0.0);
}

}  // namespace
}  // namespace penumbra
