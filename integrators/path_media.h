// The media along a camera path, shared by the integrators: which volume the path is in,
// what each segment's medium transmits, the media on both sides of a surface for shadow
// rays, and the RGB channel that a dispersive volume made the path follow.
#pragma once

#include "core/media/medium_stack.h"
#include "core/sampling/sampler.h"
#include "integrators/integrator.h"

namespace penumbra {

// Camera rays start outside all media (a camera inside a volume does not see it).
struct PathMedia {
    MediumStack stack;
    int channel = -1;  // KHR_materials_dispersion: the channel the path follows; -1 none
};

// The media on the two sides of a shading point: where wo arrived from, and beyond the
// surface (what a transmitted shadow ray or sample travels through). Null: no medium.
struct SideMedia {
    const Medium* wo_side = nullptr;
    const Medium* far_side = nullptr;
};

// Transmittance of the medium the path is in (stack.current()) from ray.o over t in
// units of |ray.d|. Integrators do not attenuate escaping rays: a closed volume cannot
// be left without crossing its surface, so a stack that is not empty at escape means an
// exit missed within rounding at an edge (a chord of ~1e-6), not an infinite medium.
Spectrum segment_transmittance(const RenderContext& ctx, const MediumStack& stack, const Ray& ray,
                               float t);

// A sample crossed the surface of `material` at a hit that wo saw from its front
// (front_face) or back: the path enters that material's volume from the front and leaves
// it from the back; thin-walled materials change nothing. instance: the hit's (for
// leave_outside), -1 if unknown.
void cross_surface(const RenderContext& ctx, MediumStack& stack, int material, bool front_face,
                   int instance = -1);

// At a hit at p: drops the volumes whose instance p lies clearly outside of (an entry
// through a face the ray only skimmed within rounding; MediumSet::surely_outside).
inline void leave_outside(const RenderContext& ctx, MediumStack& stack, Vec3 p) {
    if (!stack.empty())
        stack.leave_where([&](int instance) { return ctx.media.surely_outside(instance, p); });
}

SideMedia side_media(const RenderContext& ctx, const MediumStack& stack, int material,
                     bool front_face);

// What shade() needs from the path at a hit of `material` seen from its front or back:
// the dispersion channel, and for a volume boundary the relative IOR, that of the medium
// beyond (the stack after crossing) over that of the medium the path is in, each at the
// channel's wavelength and 1 outside all volumes. At a boundary inside the region the
// stack already assigns to the same medium (an inner face of overlapping volumes) the
// ratio is 1: no interface. Leaving a volume the path is not in (flipped winding, a
// camera inside) falls back to the material against IOR 1.
PathVolume path_volume(const RenderContext& ctx, const PathMedia& media, int material,
                       bool front_face);

// At a hit of `material`: when it is the path's first dispersive volume that transmits,
// picks one RGB channel uniformly with one sampler dimension, keeps beta on that channel
// only, times 3 (an unbiased one-sample estimate of the three), and returns it for
// shade(); later dispersive hits keep that channel. Draws nothing for other materials,
// so scenes without dispersion sample exactly as before.
int dispersion_channel(const RenderContext& ctx, PathMedia& media, int material, Sampler& sampler,
                       Spectrum& beta);

}  // namespace penumbra
