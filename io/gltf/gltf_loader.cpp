// The glTF entry point: parsing (gltf_parse.h), extension policy, then meshes, materials
// and the node tree (gltf_mesh.cpp, material/gltf_material.cpp, gltf_nodes.cpp).
#include "io/gltf/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>

#include "core/log.h"
#include "io/gltf/animation/gltf_animation.h"
#include "io/gltf/compression/gltf_compression.h"
#include "io/gltf/gltf_context.h"
#include "io/gltf/gltf_parse.h"
#include "io/gltf/animation/gltf_deform.h"
#include "io/gltf/gltf_mesh_checks.h"
#include "io/gltf/animation/gltf_node_motion.h"
#include "io/gltf/gltf_signature.h"
#include "io/gltf/animation/gltf_skin_weights.h"
#include "io/gltf/gltf_variants.h"
#include "io/color/scene_color.h"

namespace penumbra {

namespace {

void check_asset_and_extensions(const GltfContext& ctx) {
    const tinygltf::Asset& asset = ctx.model.asset;
    if (asset.version.compare(0, 2, "2.") != 0)
        ctx.fail("asset", "version '" + asset.version + "' is not glTF 2.x");
    if (!asset.minVersion.empty() && asset.minVersion != "2.0")
        ctx.fail("asset", "minVersion '" + asset.minVersion + "' is newer than 2.0");
    for (const std::string& name : ctx.model.extensionsRequired)
        if (!is_supported_extension(name))
            ctx.fail("extensionsRequired", "unsupported extension '" + name + "'");
    for (const std::string& name : ctx.model.extensionsUsed)
        if (!is_supported_extension(name))
            ctx.warn_once("extensionsUsed", "ignoring unsupported optional extension '" + name + "'");
}

// The glTF scene to load: the caller's choice, else the file's default, else scene 0;
// -1 when the file has no scenes.
int choose_scene(const GltfContext& ctx, int requested) {
    const size_t count = ctx.model.scenes.size();
    if (requested >= 0) {
        ctx.check_index("scenes", "requested scene", requested, count, "scenes");
        return requested;
    }
    if (ctx.model.defaultScene != -1) {
        ctx.check_index("scene", "default scene", ctx.model.defaultScene, count, "scenes");
        return ctx.model.defaultScene;
    }
    return count > 0 ? 0 : -1;
}

// Wall and process CPU time since the previous lap.
class StageClock {
public:
    StageClock() : m_wall(std::chrono::steady_clock::now()), m_cpu(std::clock()) {}
    GltfLoadStats::Stage lap() {
        const auto wall = std::chrono::steady_clock::now();
        const std::clock_t cpu = std::clock();
        const GltfLoadStats::Stage s{std::chrono::duration<double>(wall - m_wall).count(),
                                     double(cpu - m_cpu) / CLOCKS_PER_SEC};
        m_wall = wall;
        m_cpu = cpu;
        return s;
    }

private:
    std::chrono::steady_clock::time_point m_wall;
    std::clock_t m_cpu;
};

}  // namespace

Scene load_gltf(const std::string& path, const GltfLoadOptions& options, GltfLoadStats* stats) {
    GltfLoadStats local;
    GltfLoadStats& st = stats ? *stats : local;
    StageClock clock;
    tinygltf::Model model = parse_gltf(path, options.strict);
    st.parse = clock.lap();
    GltfContext ctx{model, path, options.rec709_to_working, options.light_units};
    ctx.strict = options.strict;
    ctx.max_texture_pixels = options.max_texture_pixels;
    check_asset_and_extensions(ctx);
    ctx.variant = find_variant(ctx, options.variant);

    const Shutter shutter{options.shutter_open, options.shutter_close};
    if (!std::isfinite(shutter.open) || !std::isfinite(shutter.close) ||
        shutter.close < shutter.open)
        throw SceneError(path + ": shutter [" + std::to_string(shutter.open) + ", " +
                         std::to_string(shutter.close) + "] s: it must be finite and open "
                         "no later than it closes");

    Scene scene;
    scene.source = path;
    scene.generator = model.asset.generator;
    scene.shutter_open = shutter.open;
    scene.shutter_close = shutter.close;
    std::vector<MeshOrigin> origins;
    MeshChecks mesh_checks(ctx);
    load_meshes(ctx, scene, origins, mesh_checks);
    st.meshes = clock.lap();
    // Parsed once the materials are read (their messages first); animated materials
    // read their values from them.
    std::optional<GltfAnimations> parsed;
    auto animations = [&]() -> const GltfAnimations& {
        if (!parsed) parsed.emplace(ctx);
        return *parsed;
    };
    load_materials(ctx, animations, shutter, scene);
    // The images are decoded: their encoded bytes (from URIs) are not needed any more.
    for (tinygltf::Image& image : model.images) std::vector<unsigned char>().swap(image.image);
    convert_scene_colors(scene, options.rec709_to_working);
    st.materials = clock.lap();
    const NodeMotion motion(ctx, animations(), shutter);
    const int scene_index = choose_scene(ctx, options.scene);
    if (scene_index >= 0)
        load_nodes(ctx, scene_index, motion, origins, scene);
    else
        ctx.warn("scenes", "the file defines no scene; nothing will be rendered");
    // Summary warnings come last: under --strict, an element's own error is reported
    // before them, as without them.
    mesh_checks.report();
    warn_unnormalized_skin_weights(ctx, scene, origins);
    st.nodes = clock.lap();
    return scene;
}

}  // namespace penumbra
