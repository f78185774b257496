// Internal to io/: KHR_animation_pointer on materials, lights and cameras. The loader reads
// an animated object from a copy of its JSON with the animated values written in
// (gltf_pointer.h), so the values pass the same checks and conversions as the file's; and
// where they change within the shutter, it reads one copy per time step.
#pragma once

#include <string>
#include <vector>

#include "io/gltf/animation/gltf_animation.h"
#include "io/gltf/gltf_context.h"
#include "io/gltf/animation/gltf_node_motion.h"

namespace penumbra {

// Time steps for a material, light or camera whose properties change within the shutter:
// the composite trapezoid rule over 64 intervals (a hit takes the nearest step), exact
// for values linear in time, within (1/64)^2 / 12 of the shutter's range times the
// second derivative otherwise.
constexpr int kPropertySteps = kMaxTimeSteps;

// The object's channels that name a property it defines; one warning (per kind and file)
// lists those that do not, which are ignored. `el` names the object ("materials[3]").
template <typename Object>
std::vector<PropertyChannel> usable_channels(const GltfContext& ctx, const std::string& el,
                                             const Object& object,
                                             const std::vector<PropertyChannel>& channels) {
    std::vector<PropertyChannel> out;
    for (const PropertyChannel& ch : channels) {
        Object copy = object;
        const std::vector<double> v = ch.curve->sample(ch.curve->times.front());
        if (write_property(copy, ch.property, v.data(), ch.width))
            out.push_back(ch);
        else
            ctx.warn("animations", ch.channel + " animates " + el + "/" + ch.property +
                                       ", which the asset does not define; ignored");
    }
    return out;
}

// A copy of the object with every channel's value at animation time t written in.
template <typename Object>
Object animated(const Object& object, const std::vector<PropertyChannel>& channels, double t) {
    Object copy = object;
    for (const PropertyChannel& ch : channels) {
        const std::vector<double> v = ch.curve->sample(t);
        write_property(copy, ch.property, v.data(), ch.width);
    }
    return copy;
}

// Whether any of the curves takes another value inside the shutter than at its opening.
bool changes_within(const std::vector<PropertyChannel>& channels, const Shutter& shutter);

}  // namespace penumbra
