#include "io/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "support/gltf_builder.h"

namespace penumbra {
namespace {

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t files_in(const std::string& dir) {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
    return n;
}

TEST(AtomicFile, ReplacesTheFileWhole) {
    const test::ScratchDir dir;
    const std::string path = dir.write("convergence.csv", "old\n");
    write_text_file(path, "spp,mse\n1,0.5\n");
    EXPECT_EQ(read(path), "spp,mse\n1,0.5\n");
    EXPECT_EQ(files_in(dir.file("")), 1u);  // no temporary left behind
}

TEST(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
    const test::ScratchDir dir;
    const std::string path = dir.write("summary.txt", "a good summary\n");
    EXPECT_THROW(write_file_atomically(path,
                                       [](const std::string& tmp) {
                                           std::ofstream(tmp) << "half a summ";
                                           throw std::runtime_error("killed");
                                       }),
                 std::runtime_error);
    EXPECT_EQ(read(path), "a good summary\n");
    EXPECT_EQ(files_in(dir.file("")), 1u);
}

TEST(AtomicFile, CreatesMissingFolders) {
    const test::ScratchDir dir;
    const std::string path = dir.file("a/b/plot.svg");
    write_text_file(path, "<svg/>");
    EXPECT_EQ(read(path), "<svg/>");
}

TEST(AtomicFile, AnUnwritableFolderIsAClearError) {
    const test::ScratchDir dir;
    const std::string blocker = dir.write("file", "x");
    // A regular file where the folder should be: nothing can be created under it.
    try {
        write_text_file(blocker + "/out.csv", "x");
        FAIL() << "expected an error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("out.csv"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace penumbra
