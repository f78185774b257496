// End-to-end tests of `penumbra converge`: error falls as 1/spp for independent samples,
// the CSV, SVG plot and summary it writes are complete and well formed, and --denoise
// gives a denoised series beside the raw one.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using test::run_penumbra;

// A diffuse floor under a small emitting square, seen from above without the emitter in
// view: every pixel has a smooth, moderate variance, so the image's MSE is an average
// over many similar pixels rather than a few fireflies, and its slope is well measured.
std::string write_area_light_scene(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    const float s = 20, h = 1, e = 0.3f;
    // Floor (normal +y) then emitter at y = h (normal -y), counter-clockwise seen from
    // the side the normal points to.
    const std::vector<float> pos = {-s, 0, s,  s, 0, s,  s, 0, -s,  -s, 0, -s,
                                    -e, h, -e, e, h, -e, e, h, e,   -e, h, e};
    const std::vector<float> nrm = {0, 1, 0,  0, 1, 0,  0, 1, 0,  0, 1, 0,
                                    0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0};
    const std::vector<uint16_t> floor_idx = {0, 1, 2, 0, 2, 3}, light_idx = {4, 5, 6, 4, 6, 7};
    const int p = b.add(pos, test::kFloat, "VEC3", "\"min\":[-20,0,-20],\"max\":[20,1,20]");
    const int n = b.add(nrm, test::kFloat, "VEC3");
    const int fi = b.add(floor_idx, test::kUShort, "SCALAR");
    const int li = b.add(light_idx, test::kUShort, "SCALAR");
    auto prim = [&](int indices, int material) {
        return "{\"attributes\":{\"POSITION\":" + std::to_string(p) +
               ",\"NORMAL\":" + std::to_string(n) + "},\"indices\":" + std::to_string(indices) +
               ",\"material\":" + std::to_string(material) + "}";
    };
    const std::string members =
        "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.8,0.8,1],"
        "\"metallicFactor\":0,\"roughnessFactor\":1}},"
        "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,0,1],\"metallicFactor\":0},"
        "\"emissiveFactor\":[1,1,1],\"doubleSided\":true}],"
        "\"meshes\":[{\"primitives\":[" + prim(fi, 0) + "," + prim(li, 1) + "]}],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,"
        "\"aspectRatio\":1,\"znear\":0.01}}],"
        // Looking straight down from below the emitter, at height 0.8.
        "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0.8,0],"
        "\"rotation\":[-0.70710678,0,0,0.70710678]}],"
        "\"scenes\":[{\"nodes\":[0,1]}],\"scene\":0";
    return b.write(dir, "area-light.gltf", members, test::BufferStorage::DataUri);
}

std::string read_text(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

struct Row {
    std::string config;
    double spp, seconds, mse, relmse, mse_x_time;
};

// Parses convergence.csv, checking its header and that every field is a number.
std::vector<Row> read_csv(const std::string& path) {
    std::istringstream in(read_text(path));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line,
              "config,spp,seconds,cpu_seconds,mse,relmse,mse_x_time,relmse_x_time,mean_spp,"
              "target_error");
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string f[10];
        for (std::string& v : f) std::getline(fields, v, ',');
        Row r{f[0], std::stod(f[1]), std::stod(f[2]), std::stod(f[4]), std::stod(f[5]),
              std::stod(f[6])};
        EXPECT_GE(std::stod(f[3]), 0) << "cpu_seconds";
        // The default clock is wall time: efficiency columns use "seconds".
        const double relmse_x_time = std::stod(f[7]);
        EXPECT_NEAR(r.mse_x_time, r.mse * r.seconds, 1e-4 * r.mse * r.seconds + 1e-12);
        EXPECT_NEAR(relmse_x_time, r.relmse * r.seconds, 1e-4 * r.relmse * r.seconds + 1e-12);
        // Without --target-error every pixel takes the checkpoint's spp.
        EXPECT_EQ(std::stod(f[8]), r.spp);
        EXPECT_EQ(std::stod(f[9]), 0.0);
        rows.push_back(r);
    }
    return rows;
}

// Least squares of log(mse) on log(spp), computed here independently of core/.
double slope(const std::vector<Row>& rows) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(rows.size());
    for (const Row& r : rows) {
        const double x = std::log(r.spp), y = std::log(r.mse);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Checks the SVG's frame and returns its series polylines' point lists.
std::vector<std::string> svg_series(const std::string& svg) {
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
    EXPECT_NE(svg.find("render time (s, wall clock)"), std::string::npos);
    EXPECT_NE(svg.find("relMSE"), std::string::npos);
    std::vector<std::string> series;
    const std::regex polyline("<polyline class=\"series\" points=\"([^\"]*)\"");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline);
         it != std::sregex_iterator(); ++it)
        series.push_back((*it)[1]);
    return series;
}

TEST(ConvergeCli, MseFallsAsOneOverSppAndFilesAreWellFormed) {
    const test::ScratchDir dir;
    const std::string scene = write_area_light_scene(dir);
    const test::CliResult r = run_penumbra(
        {"converge", scene, "--reference-spp", "512", "-o", dir.file("conv"), "--width", "32",
         "--max-spp", "32", "--sampler", "independent", "--target-relmse", "0.001", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;

    const std::vector<Row> rows = read_csv(dir.file("conv/convergence.csv"));
    ASSERT_EQ(rows.size(), 6u);  // 1, 2, 4, 8, 16, 32 spp
    for (size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].config, "default");
        EXPECT_EQ(rows[i].spp, double(1 << i));
        EXPECT_GT(rows[i].seconds, 0);
        if (i == 0) continue;
        EXPECT_LT(rows[i].mse, rows[i - 1].mse) << "at " << rows[i].spp << " spp";
        EXPECT_LT(rows[i].relmse, rows[i - 1].relmse) << "at " << rows[i].spp << " spp";
    }
    // Independent samples: MSE = variance / spp, so the log-log slope is -1 (a little
    // shallower from the reference's own noise, 1/16 of the last image's).
    const double k = slope(rows);
    EXPECT_GE(k, -1.2);
    EXPECT_LE(k, -0.8);

    // The summary reports the same slope and a time to the target.
    const std::string summary = read_text(dir.file("conv/summary.txt"));
    char expected[32];
    std::snprintf(expected, sizeof expected, "%.3f", k);
    EXPECT_NE(summary.find(expected), std::string::npos) << summary;
    EXPECT_NE(summary.find("time to relMSE 0.001"), std::string::npos) << summary;
    EXPECT_NE(r.output.find(expected), std::string::npos) << "stdout has the summary";

    const std::vector<std::string> series = svg_series(read_text(dir.file("conv/convergence.svg")));
    ASSERT_EQ(series.size(), 1u);
    std::istringstream points(series[0]);
    std::string point;
    int n = 0;
    while (points >> point) {
        double x = 0, y = 0;
        ASSERT_EQ(std::sscanf(point.c_str(), "%lf,%lf", &x, &y), 2) << point;
        EXPECT_TRUE(x >= 0 && x <= 760 && y >= 0 && y <= 480) << point;
        ++n;
    }
    EXPECT_EQ(n, 6);
}

TEST(ConvergeCli, ComparesConfigurationsAgainstAGivenReference) {
    const test::ScratchDir dir;
    const std::string scene = write_area_light_scene(dir);
    ASSERT_EQ(run_penumbra({"render", scene, "-o", dir.file("ref.exr"), "--width", "24",
                            "--spp", "64", "--seed", "9", "-q", "--no-preview"})
                  .status,
              0);
    // The reference sets the size: no --width here.
    const test::CliResult r = run_penumbra(
        {"converge", scene, "--reference", dir.file("ref.exr"), "-o", dir.file("cmp"),
         "--max-spp", "4", "--compare", "indep=--sampler independent;sobol=--sampler sobol",
         "--config", "bsdf:--strategy bsdf", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    std::map<std::string, int> rows;
    for (const Row& row : read_csv(dir.file("cmp/convergence.csv"))) ++rows[row.config];
    EXPECT_EQ(rows, (std::map<std::string, int>{{"bsdf", 3}, {"indep", 3}, {"sobol", 3}}));
    const std::string svg = read_text(dir.file("cmp/convergence.svg"));
    EXPECT_EQ(svg_series(svg).size(), 3u);
    for (const char* name : {">indep<", ">sobol<", ">bsdf<"})
        EXPECT_NE(svg.find(name), std::string::npos) << "legend entry " << name;
    EXPECT_NE(read_text(dir.file("cmp/summary.txt")).find("24x24"), std::string::npos);
}

TEST(ConvergeCli, SweepsAdaptiveTargetsAndSplitsBiasFromVariance) {
    const test::ScratchDir dir;
    const std::string scene = write_area_light_scene(dir);
    ASSERT_EQ(run_penumbra({"render", scene, "-o", dir.file("ref.exr"), "--width", "24",
                            "--spp", "256", "--seed", "9", "-q", "--no-preview"})
                  .status,
              0);
    const test::CliResult r = run_penumbra(
        {"converge", scene, "--reference", dir.file("ref.exr"), "-o", dir.file("bv"),
         "--min-spp", "16", "--max-spp", "64", "--bias-variance", "--config", "uniform:",
         "--config", "adaptive:--target-error 0.3", "--config", "clamp:--clamp-indirect 0.5",
         "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream in(read_text(dir.file("bv/convergence.csv")));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "config,spp,seconds,cpu_seconds,mse,relmse,mse_x_time,relmse_x_time,"
                    "mean_spp,target_error,variance,bias2");
    std::vector<double> targets;
    int rows = 0;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string f[12];
        for (std::string& v : f) std::getline(fields, v, ',');
        ++rows;
        const double relmse = std::stod(f[5]), variance = std::stod(f[10]);
        EXPECT_GT(variance, 0) << line;
        EXPECT_NEAR(variance + std::stod(f[11]), relmse, 1e-5 * relmse) << line;
        if (f[0] == "adaptive") {
            targets.push_back(std::stod(f[9]));
            EXPECT_LE(std::stod(f[8]), 64.0);  // mean spp within --max-spp
        } else {
            EXPECT_EQ(std::stod(f[9]), 0.0);
        }
    }
    EXPECT_EQ(rows, 9);
    // Three targets, each 1/sqrt(2) of the one before, ending at the configuration's.
    ASSERT_EQ(targets.size(), 3u);
    EXPECT_NEAR(targets[0], 0.6, 1e-5);
    EXPECT_NEAR(targets[1], 0.3 * std::sqrt(2.0), 1e-5);
    EXPECT_NEAR(targets[2], 0.3, 1e-6);
    EXPECT_NE(read_text(dir.file("bv/summary.txt")).find("bias^2"), std::string::npos);
}

TEST(ConvergeCli, DenoiseGivesRawAndDenoisedSeriesSideBySide) {
    const test::ScratchDir dir;
    const std::string scene = write_area_light_scene(dir);
    const test::CliResult r = run_penumbra(
        {"converge", scene, "--reference-spp", "64", "--width", "24", "-o", dir.file("dn"),
         "--max-spp", "4", "--config", "plain:", "--config", "dn:--denoise", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream in(read_text(dir.file("dn/convergence.csv")));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line,
              "config,spp,seconds,cpu_seconds,mse,relmse,mse_x_time,relmse_x_time,"
              "mean_spp,target_error,denoised,relmse_estimate");
    // Per configuration and denoised flag: the spp column and the relMSEs.
    std::map<std::string, std::vector<double>> spp, relmse, estimate;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string f[12];
        for (std::string& v : f) std::getline(fields, v, ',');
        const std::string key = f[0] + "/" + f[10];
        spp[key].push_back(std::stod(f[1]));
        relmse[key].push_back(std::stod(f[5]));
        if (f[10] == "1")
            estimate[key].push_back(std::stod(f[11]));
        else
            EXPECT_EQ(f[11], "") << line;
    }
    // The denoised series starts at 2 spp, where each half has a sample.
    const std::vector<double> sweep = {1, 2, 4}, denoised = {2, 4};
    EXPECT_EQ(spp, (std::map<std::string, std::vector<double>>{
                       {"plain/0", sweep}, {"dn/0", sweep}, {"dn/1", denoised}}));
    // The denoised series measures other images than the raw one, from the same renders.
    EXPECT_NE(std::vector<double>(relmse["dn/0"].begin() + 1, relmse["dn/0"].end()),
              relmse["dn/1"]);
    ASSERT_EQ(estimate["dn/1"].size(), 2u);
    for (double e : estimate["dn/1"]) EXPECT_TRUE(std::isfinite(e)) << e;
    const std::string svg = read_text(dir.file("dn/convergence.svg"));
    EXPECT_EQ(svg_series(svg).size(), 3u);
    EXPECT_NE(svg.find(">dn denoised<"), std::string::npos);
    const std::string summary = read_text(dir.file("dn/summary.txt"));
    EXPECT_NE(summary.find("dn denoised"), std::string::npos) << summary;
    EXPECT_NE(summary.find("raw and denoised"), std::string::npos) << summary;
}

TEST(ConvergeCli, BadConfigurationOrMissingReferenceIsAnError) {
    const test::ScratchDir dir;
    const std::string scene = write_area_light_scene(dir);
    test::CliResult r = run_penumbra({"converge", scene, "-o", dir.file("x"), "--config",
                                      "bad:--sampler nope", "--reference-spp", "4"});
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("configuration 'bad'"), std::string::npos) << r.output;
    r = run_penumbra({"converge", scene, "-o", dir.file("x")});
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--reference"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace penumbra
