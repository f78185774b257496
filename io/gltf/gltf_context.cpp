#include "io/gltf/gltf_context.h"

#include "core/log.h"

namespace penumbra {

void GltfContext::warn(const std::string& element, const std::string& problem) const {
    if (silent) return;
    if (strict) fail(element, problem + " [--strict]");
    LOG_WARNING(file << ": " << element << ": " << problem);
}

void GltfContext::warn_once(const std::string& element, const std::string& problem) const {
    if (silent) return;
    if (strict) fail(element, problem + " [--strict]");
    log_once(LogLevel::Warning, file + ": " + element + ": " + problem);
}

}  // namespace penumbra
