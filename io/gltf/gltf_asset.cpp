// The glTF entry point: parsing (gltf_parse.h) and extension policy once per file, then
// meshes and materials (gltf_mesh.cpp, material/gltf_material.cpp) once where no animation
// changes them, and the node tree (gltf_nodes.cpp) at every shutter.
#include "io/gltf/gltf_asset.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "io/color/scene_color.h"
#include "io/gltf/animation/gltf_frame_neighbours.h"
#include "io/gltf/animation/gltf_animation.h"
#include "io/gltf/animation/gltf_node_motion.h"
#include "io/gltf/animation/gltf_skin_weights.h"
#include "io/gltf/gltf_context.h"
#include "io/gltf/gltf_mesh_checks.h"
#include "io/gltf/gltf_parse.h"
#include "io/gltf/gltf_variants.h"

namespace penumbra {

struct GltfAssetState {
    std::string path;
    GltfLoadOptions options;
    tinygltf::Model model;
    std::unique_ptr<GltfContext> ctx;  // refers to model
    // Parsed once the materials are read (their messages first); animated materials read
    // their values from them.
    std::optional<GltfAnimations> animations;
    size_t parses = 0, static_builds = 0;
    // The last parse's time, until a scene_at reports it.
    std::optional<GltfLoadStats::Stage> parse_time;
    // The encoded image bytes were dropped after decoding: building the shared parts
    // again needs the file parsed again.
    bool images_released = false;
    // Meshes, objects, materials and images of the last build, and how many of each
    // belong to it (poses append deformed meshes and their objects, and the material of
    // hidden instances); `kept` holds them between a recycle() and the next scene_at().
    std::optional<Scene> kept;
    size_t meshes = 0, objects = 0, materials = 0;
    std::vector<MeshOrigin> origins;  // of the shared meshes
    // No material is animated: the shared parts are the same at every shutter.
    bool reusable = false;
    // The mesh checks of the last build, reported once, after its first pose's nodes.
    std::unique_ptr<MeshChecks> checks;
};

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
            ctx.warn_once("extensionsUsed",
                          "ignoring unsupported optional extension '" + name + "'");
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

void parse(GltfAssetState& s) {
    StageClock clock;
    s.ctx.reset();
    s.animations.reset();
    s.model = parse_gltf(s.path, s.options.strict);
    ++s.parses;
    s.images_released = false;
    s.parse_time = clock.lap();
    s.ctx = std::make_unique<GltfContext>(
        GltfContext{s.model, s.path, s.options.rec709_to_working, s.options.light_units});
    GltfContext& ctx = *s.ctx;
    ctx.strict = s.options.strict;
    ctx.max_texture_pixels = s.options.max_texture_pixels;
    check_asset_and_extensions(ctx);
    ctx.variant = find_variant(ctx, s.options.variant);
}

Shutter checked_shutter(const std::string& path, double open, double close) {
    const Shutter shutter{open, close};
    if (!std::isfinite(shutter.open) || !std::isfinite(shutter.close) ||
        shutter.close < shutter.open)
        throw SceneError(path + ": shutter [" + std::to_string(shutter.open) + ", " +
                         std::to_string(shutter.close) +
                         "] s: it must be finite and open "
                         "no later than it closes");
    return shutter;
}

const GltfAnimations& animations_of(GltfAssetState& s) {
    if (!s.animations) s.animations.emplace(*s.ctx);
    return *s.animations;
}

bool animates_materials(const GltfAnimations& animations, size_t materials) {
    for (size_t i = 0; i < materials; ++i)
        if (!animations.properties(PointerObject::Material, int(i)).empty()) return true;
    return false;
}

// Meshes, materials and their images into an empty scene, as the shutter poses the
// materials.
void build_static(GltfAssetState& s, const Shutter& shutter, Scene& scene, GltfLoadStats& stats,
                  StageClock& clock) {
    if (s.images_released) parse(s);
    const GltfContext& ctx = *s.ctx;
    scene.source = s.path;
    scene.generator = s.model.asset.generator;
    s.origins.clear();
    s.checks = std::make_unique<MeshChecks>(ctx);
    load_meshes(ctx, scene, s.origins, *s.checks);
    stats.meshes = clock.lap();
    load_materials(
        ctx, [&s]() -> const GltfAnimations& { return animations_of(s); }, shutter, scene);
    s.reusable = !animates_materials(animations_of(s), s.model.materials.size());
    // The images are decoded: their encoded bytes (from URIs) are only needed again where
    // the materials are read again at every shutter.
    if (s.reusable) {
        for (tinygltf::Image& image : s.model.images)
            std::vector<unsigned char>().swap(image.image);
        s.images_released = true;
    }
    convert_scene_colors(scene, s.options.rec709_to_working);
    s.meshes = scene.meshes.size();
    s.objects = scene.objects.size();
    s.materials = scene.materials.size();
    ++s.static_builds;
    stats.materials = clock.lap();
}

}  // namespace

GltfAsset::GltfAsset(const std::string& path, const GltfLoadOptions& options)
    : m(std::make_unique<GltfAssetState>()) {
    m->path = path;
    m->options = options;
    parse(*m);
}

GltfAsset::~GltfAsset() = default;

Scene GltfAsset::scene_at(double shutter_open, double shutter_close, GltfLoadStats* stats) {
    GltfLoadStats local;
    GltfLoadStats& st = stats ? *stats : local;
    const Shutter shutter = checked_shutter(m->path, shutter_open, shutter_close);
    StageClock clock;
    Scene scene;
    if (m->kept) {
        scene = std::move(*m->kept);
        m->kept.reset();
        st.meshes = st.materials = {};
        clock.lap();
    } else {
        build_static(*m, shutter, scene, st, clock);
    }
    scene.shutter_open = shutter.open;
    scene.shutter_close = shutter.close;
    const GltfContext& ctx = *m->ctx;
    const NodeMotion motion(ctx, animations_of(*m), shutter);
    const int scene_index = choose_scene(ctx, m->options.scene);
    scene.frame_neighbours.reset();  // a recycled scene's are another frame's
    start_frame_neighbours(ctx, shutter, m->options.neighbour_frame_offset, scene);
    if (scene_index >= 0)
        load_nodes(ctx, scene_index, motion, m->origins, scene);
    else
        ctx.warn("scenes", "the file defines no scene; nothing will be rendered");
    finish_frame_neighbours(ctx, motion, scene);
    // Summary warnings come last: under --strict, an element's own error is reported
    // before them, as without them. They are about the file, so a build reports them once.
    if (m->checks) {
        const std::unique_ptr<MeshChecks> checks = std::move(m->checks);
        checks->report();
        warn_unnormalized_skin_weights(ctx, scene, m->origins);
    }
    st.nodes = clock.lap();
    st.parse = m->parse_time.value_or(GltfLoadStats::Stage{});
    st.parsed = m->parse_time.has_value();
    m->parse_time.reset();
    return scene;
}

void GltfAsset::recycle(Scene&& scene) {
    if (!m->reusable || m->kept || scene.meshes.size() < m->meshes ||
        scene.objects.size() < m->objects || scene.materials.size() < m->materials)
        return;
    Scene kept;
    kept.source = std::move(scene.source);
    kept.generator = std::move(scene.generator);
    scene.meshes.resize(m->meshes);
    scene.objects.resize(m->objects);
    scene.materials.resize(m->materials);
    kept.meshes = std::move(scene.meshes);
    kept.objects = std::move(scene.objects);
    kept.materials = std::move(scene.materials);
    kept.images = std::move(scene.images);
    kept.textures = std::move(scene.textures);
    m->kept = std::move(kept);
}

bool GltfAsset::keeps_geometry(const Scene& scene) const {
    return m->reusable && scene.meshes.size() == m->meshes && scene.objects.size() == m->objects;
}

size_t GltfAsset::parses() const { return m->parses; }
size_t GltfAsset::static_builds() const { return m->static_builds; }

}  // namespace penumbra
