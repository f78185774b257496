#include "integrators/integrator.h"

#include <stdexcept>

#include "integrators/basic_integrator.h"
#include "integrators/debug_integrator.h"
#include "integrators/direct_integrator.h"
#include "integrators/path_integrator.h"

namespace penumbra {

const std::vector<std::pair<std::string, std::string>>& integrator_names() {
    static const std::vector<std::pair<std::string, std::string>> names = {
        {"path", "path tracing with next-event estimation and MIS (the default)"},
        {"direct", "direct light only: many light and BSDF samples, specular recursion"},
        {"basic", "classic ray tracer: direct light from punctual lights, mirror recursion"},
        {"normal", "debug: world shading normal as 0.5 n + 0.5"},
        {"geometric-normal", "debug: world geometric normal as 0.5 n + 0.5"},
        {"albedo", "debug: base colour at the first hit"},
        {"depth", "debug: distance to the first hit"},
        {"uv", "debug: TEXCOORD_0 as (u, v, 0)"},
        {"instance", "debug: a colour per instance"},
    };
    return names;
}

std::unique_ptr<Integrator> make_integrator(const std::string& name,
                                            const IntegratorOptions& options) {
    if (name == "path") return std::make_unique<PathIntegrator>(options);
    if (name == "direct") return std::make_unique<DirectIntegrator>(options);
    if (name == "basic") return std::make_unique<BasicIntegrator>(options);
    if (name == "normal") return std::make_unique<DebugIntegrator>(DebugView::ShadingNormal);
    if (name == "geometric-normal")
        return std::make_unique<DebugIntegrator>(DebugView::GeometricNormal);
    if (name == "albedo") return std::make_unique<DebugIntegrator>(DebugView::Albedo);
    if (name == "depth") return std::make_unique<DebugIntegrator>(DebugView::Depth);
    if (name == "uv") return std::make_unique<DebugIntegrator>(DebugView::Uv);
    if (name == "instance") return std::make_unique<DebugIntegrator>(DebugView::Instance);
    std::string list;
    for (const auto& [n, d] : integrator_names()) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown integrator '" + name + "' (expected one of: " + list +
                                ")");
}

LightStrategy parse_light_strategy(const std::string& name) {
    if (name == "mis") return LightStrategy::Mis;
    if (name == "bsdf") return LightStrategy::BsdfOnly;
    if (name == "light") return LightStrategy::LightOnly;
    throw std::invalid_argument("unknown light strategy '" + name +
                                "' (expected mis, bsdf or light)");
}

}  // namespace penumbra
