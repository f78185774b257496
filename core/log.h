// The one logger. Library code reports through it (never std::cout); the app chooses
// the level. Thread-safe: each call writes one whole line to stderr.
#pragma once

#include <sstream>
#include <string>

namespace penumbra {

enum class LogLevel { Debug = 0, Info = 1, Warning = 2, Error = 3, Silent = 4 };

void set_log_level(LogLevel level);
LogLevel log_level();
void log_message(LogLevel level, const std::string& msg);

// Reports a message once per process (e.g. an unknown optional glTF extension).
void log_once(LogLevel level, const std::string& msg);

}  // namespace penumbra

#define PENUMBRA_LOG(level, expr)                                               \
    do {                                                                        \
        if (static_cast<int>(level) >= static_cast<int>(::penumbra::log_level())) { \
            std::ostringstream log_msg_;                                        \
            log_msg_ << expr;                                                   \
            ::penumbra::log_message(level, log_msg_.str());                     \
        }                                                                       \
    } while (0)
#define LOG_DEBUG(expr) PENUMBRA_LOG(::penumbra::LogLevel::Debug, expr)
#define LOG_INFO(expr) PENUMBRA_LOG(::penumbra::LogLevel::Info, expr)
#define LOG_WARNING(expr) PENUMBRA_LOG(::penumbra::LogLevel::Warning, expr)
#define LOG_ERROR(expr) PENUMBRA_LOG(::penumbra::LogLevel::Error, expr)
