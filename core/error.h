// Errors and always-on checks. Input problems are SceneError (the message names the file
// and element); broken invariants after loading are CHECK failures (file:line).
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace penumbra {

// Bad input: a scene file, image or option the user can fix. The message is complete
// and printable as one line, e.g. "scene.gltf: meshes[3].primitives[0]: ...".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A broken invariant inside the renderer: a bug, not bad input.
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

[[noreturn]] void check_failed(const char* expr, const char* file, int line,
                               const std::string& msg);

}  // namespace penumbra

#define PENUMBRA_STRINGIFY(x) #x
#define CHECK(cond, ...)                                                                 \
    do {                                                                                 \
        if (!(cond)) {                                                                   \
            std::ostringstream check_msg_;                                               \
            check_msg_ << "" __VA_ARGS__;                                                \
            ::penumbra::check_failed(#cond, __FILE__, __LINE__, check_msg_.str());       \
        }                                                                                \
    } while (0)
#ifdef NDEBUG
#define DCHECK(cond, ...) \
    do {                  \
    } while (0)
#else
#define DCHECK(cond, ...) CHECK(cond, __VA_ARGS__)
#endif
