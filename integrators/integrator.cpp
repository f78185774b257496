#include "integrators/integrator.h"

#include <stdexcept>

#include "integrators/basic_integrator.h"
#include "integrators/debug_integrator.h"
#include "integrators/direct_integrator.h"
#include "integrators/path_integrator.h"

namespace penumbra {

std::unique_ptr<Integrator> make_integrator(IntegratorType type, const IntegratorOptions& options) {
    switch (type) {
        case IntegratorType::Path: return std::make_unique<PathIntegrator>(options);
        case IntegratorType::Direct: return std::make_unique<DirectIntegrator>(options);
        case IntegratorType::Basic: return std::make_unique<BasicIntegrator>(options);
        case IntegratorType::ShadingNormal:
            return std::make_unique<DebugIntegrator>(DebugView::ShadingNormal);
        case IntegratorType::GeometricNormal:
            return std::make_unique<DebugIntegrator>(DebugView::GeometricNormal);
        case IntegratorType::Albedo: return std::make_unique<DebugIntegrator>(DebugView::Albedo);
        case IntegratorType::Depth: return std::make_unique<DebugIntegrator>(DebugView::Depth);
        case IntegratorType::Uv: return std::make_unique<DebugIntegrator>(DebugView::Uv);
        case IntegratorType::Instance: return std::make_unique<DebugIntegrator>(DebugView::Instance);
    }
    throw std::invalid_argument("unknown integrator type");
}

}  // namespace penumbra
