// End-to-end tests of the penumbra CLI: outputs, exit status, errors, determinism.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "support/paths.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

struct Result {
    int status;
    std::string output;  // stdout and stderr together
};

Result run(const std::string& args) {
    const std::string cmd = test::binary_path("bin/penumbra") + " " + args + " 2>&1";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe.get())) > 0) out.append(buf.data(), n);
    const int raw = pclose(pipe.release());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("penumbra-cli-" + std::string(::testing::UnitTest::GetInstance()
                                                   ->current_test_info()
                                                   ->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    fs::path m_dir;
};

std::string read_file(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

TEST_F(CliTest, RendersCornellBoxToExrAndPreview) {
    const Result r = run("render " + test::source_path("scenes/cornell-box.gltf") + " -o " +
                         path("cb.exr") + " --spp 2 --width 64");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("cb.exr")));
    EXPECT_TRUE(fs::exists(path("cb.png")));
    // The summary reports the phases, throughput and memory.
    for (const char* word : {"load", "build", "render", "write", "rays/s", "peak memory"})
        EXPECT_NE(r.output.find(word), std::string::npos) << word << "\n" << r.output;
}

TEST_F(CliTest, SameCommandGivesBitwiseIdenticalExrForAnyThreadCount) {
    const std::string base = "render " + test::source_path("scenes/cornell-box.gltf") +
                             " --spp 3 --width 48 --seed 7 -q --no-preview";
    ASSERT_EQ(run(base + " --threads 1 -o " + path("t1.exr")).status, 0);
    ASSERT_EQ(run(base + " --threads 2 -o " + path("t2.exr")).status, 0);
    const std::string a = read_file(path("t1.exr")), b = read_file(path("t2.exr"));
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "EXR files differ between --threads 1 and --threads 2";
}

TEST_F(CliTest, MissingFileFailsWithoutOutput) {
    const Result r = run("render " + path("nope.gltf") + " -o " + path("x.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("nope.gltf"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("x.exr")));
}

TEST_F(CliTest, BadSceneLeavesExistingOutputUntouchedAndNoTempFiles) {
    {
        std::ofstream(path("good.exr")) << "previous render";
        std::ofstream(path("broken.gltf")) << "{ \"asset\": { \"version\": \"2.0\" }, ";
    }
    const Result r = run("render " + path("broken.gltf") + " -o " + path("good.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("broken.gltf"), std::string::npos) << r.output;
    EXPECT_EQ(read_file(path("good.exr")), "previous render");
    // One line of error, no crash.
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    for (const auto& entry : fs::directory_iterator(m_dir))
        EXPECT_EQ(entry.path().filename().string().rfind(".tmp", 0), std::string::npos);
}

TEST_F(CliTest, BatchGoesOnAfterABadSceneAndReportsFailure) {
    std::ofstream(path("broken.gltf")) << "not json";
    const Result r = run("render " + path("broken.gltf") + " " +
                         test::shared_path("scenes/khronos/Box.gltf") + " --out-dir " +
                         path("renders") + " --spp 1 --width 32 -q");
    EXPECT_NE(r.status, 0);
    EXPECT_TRUE(fs::exists(path("renders/Box.exr")));
    EXPECT_FALSE(fs::exists(path("renders/broken.exr")));
}

TEST_F(CliTest, UnknownCameraIsAClearError) {
    const Result r = run("render " + test::source_path("scenes/cornell-box.gltf") +
                         " --camera side -o " + path("c.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("no camera 'side'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'front'"), std::string::npos) << r.output;
}

TEST_F(CliTest, HelpListsEveryOption) {
    const Result r = run("render --help");
    EXPECT_EQ(r.status, 0);
    for (const char* opt : {"--output", "--spp", "--width", "--height", "--threads", "--seed",
                            "--camera", "--integrator", "basic", "albedo", "--light-units",
                            "--default-light", "--no-default-light", "--exposure"})
        EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

}  // namespace
}  // namespace penumbra
