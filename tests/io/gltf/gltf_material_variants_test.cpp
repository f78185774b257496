// KHR_materials_variants: default materials without a variant, each primitive's mapped
// material with one, errors for unknown names and bad mappings; and the job file's
// "variant" key.
#include <gtest/gtest.h>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "job/job_file.h"
#include "job/option_table.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

// Two triangle primitives. Primitive 0 (material 0) maps "red" to 1 and "blue" to 2;
// primitive 1 (material 3) maps both to 2; mapping 1 of primitive 0 also lists "green",
// which primitive 1 does not map.
const char* const kMappings0 = R"([{"material": 1, "variants": [0]},
                                   {"material": 2, "variants": [1, 2]}])";
const char* const kMappings1 = R"([{"material": 2, "variants": [0, 1]}])";

std::string write_file(const ScratchDir& dir, const std::string& mappings0 = kMappings0,
                       const std::string& root = R"("extensions": {"KHR_materials_variants":
        {"variants": [{"name": "red"}, {"name": "blue"}, {"name": "green"}]}},)") {
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    auto primitive = [](int material, const std::string& mappings) {
        return R"({"attributes": {"POSITION": 0}, "material": )" + std::to_string(material) +
               R"(, "extensions": {"KHR_materials_variants": {"mappings": )" + mappings + "}}}";
    };
    const std::string members =
        R"("extensionsUsed": ["KHR_materials_variants"],)" + root +
        R"("materials": [{"name": "default"}, {"name": "red"}, {"name": "blue"},
                         {"name": "other"}],)" +
        test::one_mesh_scene(primitive(0, mappings0) + ", " + primitive(3, kMappings1));
    return b.write(dir, "variants.gltf", members, BufferStorage::DataUri);
}

std::vector<int> materials_for(const std::string& path, const std::string& variant) {
    GltfLoadOptions options;
    options.variant = variant;
    const Scene s = load_gltf(path, options);
    std::vector<int> out;
    for (const TriangleMesh& m : s.meshes) out.push_back(m.material);
    return out;
}

std::string error_of(const std::string& path, const std::string& variant) {
    try {
        materials_for(path, variant);
    } catch (const SceneError& e) {
        return std::string(e.what()).substr(path.size() + 2);
    }
    return "(loaded)";
}

TEST(GltfMaterialVariants, EachVariantPicksItsMappedMaterials) {
    ScratchDir dir;
    const std::string path = write_file(dir);
    EXPECT_EQ(materials_for(path, ""), (std::vector<int>{0, 3}));
    EXPECT_EQ(materials_for(path, "red"), (std::vector<int>{1, 2}));
    EXPECT_EQ(materials_for(path, "blue"), (std::vector<int>{2, 2}));
    // Primitive 1 does not map "green": it keeps its default material.
    EXPECT_EQ(materials_for(path, "green"), (std::vector<int>{2, 3}));
}

TEST(GltfMaterialVariants, UnknownNamesAndBadMappingsAreErrors) {
    ScratchDir dir;
    const std::string path = write_file(dir);
    EXPECT_EQ(error_of(path, "Red"),
              "extensions.KHR_materials_variants: no material variant 'Red' (the file has "
              "'red', 'blue', 'green')");
    const std::string none = write_file(dir, kMappings0, "");
    EXPECT_EQ(error_of(none, "red"),
              "extensions.KHR_materials_variants: no material variant 'red' (the file defines "
              "none)");
    const std::string el = "meshes[0].primitives[0].extensions.KHR_materials_variants";
    // Mappings are checked whether or not a variant is chosen.
    const std::string bad_material = write_file(dir, R"([{"material": 4, "variants": [0]}])");
    EXPECT_EQ(error_of(bad_material, ""),
              el + ".mappings[0]: material index 4 out of range (4 materials)");
    const std::string bad_variant = write_file(dir, R"([{"material": 1, "variants": [3]}])");
    EXPECT_EQ(error_of(bad_variant, ""),
              el + ".mappings[0]: variant index 3 out of range (3 variants)");
    const std::string no_variants = write_file(dir, R"([{"material": 1}])");
    EXPECT_EQ(error_of(no_variants, "red"),
              el + ".mappings[0]: must have an integer material and an array of variants");
    const std::string not_array = write_file(dir, R"({"material": 1})");
    EXPECT_EQ(error_of(not_array, ""), el + ": mappings must be an array");
    const std::string bad_root =
        write_file(dir, kMappings0, R"("extensions": {"KHR_materials_variants": {}},)");
    EXPECT_EQ(error_of(bad_root, "red"),
              "extensions.KHR_materials_variants: variants must be an array");
}

// A variant mapped twice in one primitive renders with the first mapping.
TEST(GltfMaterialVariants, FirstMappingWinsWhenAVariantIsMappedTwice) {
    ScratchDir dir;
    const std::string path = write_file(dir, R"([{"material": 2, "variants": [0]},
                                                 {"material": 1, "variants": [0]}])");
    EXPECT_EQ(materials_for(path, "red"), (std::vector<int>{2, 2}));
}

TEST(GltfMaterialVariants, JobFileKey) {
    const JobFile job = parse_job_file(
        R"({"defaults": {"variant": "red"}, "jobs": [{"scene": "a.gltf"},
            {"scene": "b.gltf", "variant": "blue"}]})",
        "/jobs/j.json");
    ASSERT_EQ(job.defaults.size(), 1u);
    EXPECT_EQ(job.defaults[0].option->job_key, "variant");
    EXPECT_EQ(job.defaults[0].text, "red");
    EXPECT_TRUE(job.jobs.at(0).settings.empty());
    ASSERT_EQ(job.jobs.at(1).settings.size(), 1u);
    EXPECT_EQ(job.jobs.at(1).settings[0].text, "blue");
    try {
        parse_job_file(R"({"jobs": [{"scene": "a.gltf", "variant": ""}]})", "j.json");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "j.json: jobs[0].variant: expected a non-empty string");
    }
}

}  // namespace
}  // namespace penumbra
