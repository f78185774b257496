// scripts/crosscheck/efficiency.py's measures (relMSE, efficiency, the reference-error
// correction, image reading, Cycles' timing lines) through its Python unit tests on
// synthetic images; no renderer runs, so this stays a few seconds of CPU.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/paths.h"

namespace penumbra {
namespace {

TEST(EfficiencyHarness, MetricsPassTheirUnitTestsOnSyntheticImages) {
    const std::string cmd = "cd '" + test::source_path("tests/scripts/crosscheck") +
                            "' && python3 -m unittest -q efficiency_metrics_test 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

}  // namespace
}  // namespace penumbra
