#include "integrators/path_media.h"

#include <algorithm>

#include "materials/lobes/dispersion.h"

namespace penumbra {

Spectrum segment_transmittance(const RenderContext& ctx, const MediumStack& stack, const Ray& ray,
                               float t) {
    const Medium* medium = ctx.media.interior(stack.current());
    if (!medium || medium->is_clear()) return Spectrum(1);
    const float len = length(ray.d);
    const Ray unit{ray.o, ray.d / len, 0, std::numeric_limits<float>::infinity(), ray.time, {}};
    return medium->transmittance(unit, t * len);
}

void cross_surface(const RenderContext& ctx, MediumStack& stack, int material, bool front_face,
                   int instance) {
    if (!ctx.media.has_volume(material)) return;
    if (front_face)
        stack.enter(material, instance);
    else
        stack.leave(material);
}

SideMedia side_media(const RenderContext& ctx, const MediumStack& stack, int material,
                     bool front_face) {
    MediumStack beyond = stack;
    cross_surface(ctx, beyond, material, front_face);
    return {ctx.media.interior(stack.current()), ctx.media.interior(beyond.current())};
}

namespace {

// The IOR of the medium inside `material` (1 outside all volumes) at the path's channel.
float medium_ior(const RenderContext& ctx, int material, int channel) {
    if (material < 0) return 1;
    const MaterialDesc& m = ctx.scene.material(material);
    return dispersion_ior(m.ior > 0 ? m.ior : 1.5f, m.dispersion, channel);
}

}  // namespace

PathVolume path_volume(const RenderContext& ctx, const PathMedia& media, int material,
                       bool front_face) {
    PathVolume v;
    v.dispersion_channel = media.channel;
    if (!ctx.media.has_volume(material)) return v;
    if (!front_face && !media.stack.contains(material)) return v;
    MediumStack beyond = media.stack;
    cross_surface(ctx, beyond, material, front_face);
    // Outside all volumes the ratios are ior / 1 and 1 / ior, as shade() forms them.
    v.eta = medium_ior(ctx, beyond.current(), media.channel) /
            medium_ior(ctx, media.stack.current(), media.channel);
    return v;
}

int dispersion_channel(const RenderContext& ctx, PathMedia& media, int material, Sampler& sampler,
                       Spectrum& beta) {
    if (media.channel >= 0) return media.channel;
    const MaterialDesc& m = ctx.scene.material(material);
    if (!(m.dispersion > 0) || !(m.transmission > 0) || !ctx.media.has_volume(material))
        return -1;
    media.channel = std::min(int(sampler.get_1d() * 3), 2);
    Spectrum only(0);
    only[media.channel] = 3;
    beta *= only;
    return media.channel;
}

}  // namespace penumbra
