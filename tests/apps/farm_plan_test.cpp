// The farm's plan as plain code (no cluster): work items are a pure function of the job
// file, bands tile the rows exactly, arrays are cut under MaxArraySize, and task records
// and --sbatch-args survive their round trips.
#include "apps/penumbra/farm/farm_plan.h"

#include <gtest/gtest.h>

#include "apps/penumbra/farm/farm_slurm.h"
#include "core/error.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

const char* kJob = R"({
  "defaults": {"width": 64, "spp": 2},
  "jobs": [
    {"scene": "a.gltf"},
    {"scene": "b.gltf", "frames": "1-3"},
    {"scene": "c.gltf", "bands": 4, "name": "c_banded.exr"},
    {"scene": "d.gltf", "frames": "5,7", "bands": 2}
  ]
})";

TEST(FarmPlan, WorkItemsArePureFunctionsOfTheJobFile) {
    const test::ScratchDir dir;
    const std::string job = dir.write("job.json", kJob);
    const FarmPlan a = load_farm_plan(job, 300), b = load_farm_plan(job, 60);
    // 1 + 3 frames + 4 bands + 2 frames x 2 bands.
    ASSERT_EQ(a.items.size(), 12u);
    EXPECT_EQ(plan_text(a.jobs, a.items), plan_text(b.jobs, b.items));
    EXPECT_EQ(a.items[4].job, 4u);  // c.gltf is the 5th image
    EXPECT_EQ(a.items[4].band, 0);
    EXPECT_EQ(a.items[7].band, 3);
    EXPECT_EQ(a.items[8].band, 0);
    EXPECT_EQ(a.items[0].band, -1);
    EXPECT_NE(plan_text(a.jobs, a.items).find("7 job 4 band 4/4 frame - "), std::string::npos)
        << plan_text(a.jobs, a.items);
    // A changed job file gives another plan (the task's check against plan.txt).
    const std::string changed = dir.write(
        "job2.json",
        std::string(kJob).replace(std::string(kJob).find("\"bands\": 4"), 10, "\"bands\": 3"));
    const FarmPlan c = load_farm_plan(changed, 300);
    EXPECT_EQ(c.items.size(), 11u);
}

TEST(FarmPlan, FramesPerTaskGroupsConsecutiveFramesOfOneEntry) {
    const test::ScratchDir dir;
    const std::string job = dir.write("job.json", R"({
  "defaults": {"frames_per_task": 4},
  "jobs": [
    {"scene": "a.gltf", "frames": "1-10"},
    {"scene": "a.gltf", "frames": "11-12"},
    {"scene": "b.gltf", "frames": "1-3", "bands": 2},
    {"scene": "c.gltf", "frames": "1-3", "frames_per_task": 1}
  ]
})");
    const FarmPlan p = load_farm_plan(job, 300);
    // a: 4 + 4 + 2 frames; the next entry starts its own item; bands never group; c: 1 each.
    std::vector<std::pair<size_t, size_t>> got;  // (first job, count)
    for (const WorkItem& w : p.items) got.push_back({w.job, w.count});
    const std::vector<std::pair<size_t, size_t>> expected = {
        {0, 4}, {4, 4}, {8, 2}, {10, 2}, {12, 1}, {12, 1}, {13, 1},
        {13, 1}, {14, 1}, {14, 1}, {15, 1}, {16, 1}, {17, 1}};
    EXPECT_EQ(got, expected);
    EXPECT_NE(plan_text(p.jobs, p.items).find("0 job 0-3 band - frame 1-4 "), std::string::npos)
        << plan_text(p.jobs, p.items);
}

TEST(FarmPlan, BadBandsAreNamed) {
    const test::ScratchDir dir;
    const std::string job = dir.write("job.json", R"({"jobs": [{"scene": "a.gltf", "bands": 0}]})");
    try {
        load_farm_plan(job, 300);
        FAIL() << "bands 0 accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("jobs[0].bands: 0 is not in [1, 32768]"),
                  std::string::npos)
            << e.what();
    }
}

TEST(FarmPlan, BandsTileTheRowsExactly) {
    for (int h : {1, 2, 7, 64, 1080})
        for (int n : {1, 2, 3, 4, 7, 64, 100}) {
            int next = 0;
            for (int b = 0; b < n; ++b) {
                const auto [y0, y1] = band_rows(h, b, n);
                ASSERT_EQ(y0, next) << h << " " << n << " " << b;
                ASSERT_LE(y0, y1);
                // As even as whole rows allow.
                ASSERT_LE(y1 - y0, h / n + 1);
                ASSERT_GE(y1 - y0, h / n);
                next = y1;
            }
            ASSERT_EQ(next, h);
        }
    EXPECT_EQ(band_output_path("out/c.exr", 2, 12), "out/c.band-03-of-12.exr");
    EXPECT_EQ(band_output_path("c.exr", 0, 4), "c.band-1-of-4.exr");
}

TEST(FarmPlan, ArraysAreCutUnderMaxArraySize) {
    using Chunks = std::vector<std::pair<size_t, size_t>>;
    EXPECT_EQ(array_chunks(5, 1001), (Chunks{{0, 4}}));
    EXPECT_EQ(array_chunks(1001, 1001), (Chunks{{0, 1000}}));
    EXPECT_EQ(array_chunks(2500, 1001), (Chunks{{0, 1000}, {1001, 2001}, {2002, 2499}}));
    EXPECT_EQ(array_chunks(100000, 1001).size(), 100u);
}

TEST(FarmPlan, TaskRecordsRoundTrip) {
    const test::ScratchDir dir;
    TaskRecord rec;
    rec.item = 7;
    JobResult r;
    r.scene = "s.gltf";
    r.output = "out/s.exr";
    r.message = "a \"quoted\" error\nover two lines";
    r.frame = 12;
    r.status = JobStatus::Partial;
    r.seconds = 1.5;
    r.spp = 9;
    r.rays = 1ull << 40;
    r.peak_memory = 123456789;
    rec.results = {r, r};
    rec.results[1].frame = 13;
    rec.results[1].status = JobStatus::Skipped;
    rec.band = 2;
    rec.bands = 4;
    rec.band_file = "out/s.band-3-of-4.exr";
    rec.host = "node07";
    rec.restarts = 1;
    const std::string path = task_record_path(dir.file("farm"), 7);
    write_task_record(path, rec);
    const auto back = read_task_record(path);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->item, 7u);
    ASSERT_EQ(back->results.size(), 2u);
    EXPECT_EQ(back->results[0].message, r.message);
    EXPECT_EQ(back->results[0].status, JobStatus::Partial);
    EXPECT_EQ(back->results[0].rays, r.rays);
    EXPECT_EQ(back->results[0].seconds, 1.5);
    EXPECT_EQ(back->results[0].peak_memory, r.peak_memory);
    EXPECT_EQ(back->results[1].frame, 13);
    EXPECT_EQ(back->results[1].status, JobStatus::Skipped);
    EXPECT_EQ(back->band_file, rec.band_file);
    EXPECT_EQ(back->host, "node07");
    EXPECT_EQ(back->restarts, 1);
    EXPECT_FALSE(read_task_record(dir.file("missing.json")));
}

TEST(FarmPlan, SbatchArgumentsSplitLikeAShell) {
    using Words = std::vector<std::string>;
    EXPECT_EQ(split_arguments("  --time=1:00:00   --mem=8G "),
              (Words{"--time=1:00:00", "--mem=8G"}));
    EXPECT_EQ(split_arguments("--comment 'two words' -J \"x y\""),
              (Words{"--comment", "two words", "-J", "x y"}));
    EXPECT_EQ(split_arguments(""), Words{});
    EXPECT_THROW(split_arguments("--comment 'open"), SceneError);
}

}  // namespace
}  // namespace penumbra
