#include "io/gltf/animation/gltf_frame_neighbours.h"

#include <cmath>

namespace penumbra {

namespace {

// Whether instance `inst` is placed elsewhere at other times: its node or an ancestor is
// animated. A skinned instance's vertices are in world space (its to_world is the identity
// at every time): they move through their positions.
bool instance_moves(const GltfContext& ctx, const NodeMotion& motion, const Instance& inst) {
    return ctx.model.nodes[size_t(inst.node)].skin < 0 && motion.moves(inst.node);
}

// Instance `inst` at time t. Its to_world is the node's world matrix W at shutter open,
// times its own EXT_mesh_gpu_instancing transform L where it has one; at t that is
// W(t) L = W(t) W(open)^-1 to_world.
Mat4 instance_at(const GltfContext& ctx, const NodeMotion& motion, const Instance& inst, double t) {
    const Mat4& at_frame = inst.to_world.matrix();
    if (!instance_moves(ctx, motion, inst)) return at_frame;
    const Mat4 world = motion.world(inst.node, t);
    if (!ctx.model.nodes[size_t(inst.node)].extensions.count("EXT_mesh_gpu_instancing"))
        return world;
    Mat4 open_inverse;
    // A node singular at shutter open has no instances; keep the frame's matrix if it is.
    if (!motion.world(inst.node, motion.shutter().open).inverse(&open_inverse)) return at_frame;
    return world * open_inverse * at_frame;
}

}  // namespace

void start_frame_neighbours(const GltfContext& ctx, const Shutter& shutter, double offset,
                            Scene& scene) {
    if (!(std::isfinite(offset) && offset >= 0))
        ctx.fail("animations", "the motion vectors' frame duration " + std::to_string(offset) +
                                   " s must be finite and not negative");
    if (offset == 0) return;
    FrameNeighbours& n = scene.frame_neighbours.emplace();
    n.previous.time = shutter.open - offset;
    n.next.time = shutter.open + offset;
}

void finish_frame_neighbours(const GltfContext& ctx, const NodeMotion& motion, Scene& scene) {
    if (!scene.frame_neighbours) return;
    // Where nothing moves (a still file, a million unanimated instances) nothing is kept.
    bool any = false;
    for (const Instance& inst : scene.instances) any = any || instance_moves(ctx, motion, inst);
    if (!any) return;
    for (NeighbourFrame* f : {&scene.frame_neighbours->previous, &scene.frame_neighbours->next}) {
        f->instances.reserve(scene.instances.size());
        for (const Instance& inst : scene.instances)
            f->instances.push_back(instance_at(ctx, motion, inst, f->time));
    }
}

}  // namespace penumbra
