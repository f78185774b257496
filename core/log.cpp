#include "core/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <set>

#include "core/error.h"

namespace penumbra {

namespace {
std::atomic<int> g_level{static_cast<int>(LogLevel::Info)};
std::mutex g_mutex;
}  // namespace

void set_log_level(LogLevel level) { g_level = static_cast<int>(level); }
LogLevel log_level() { return static_cast<LogLevel>(g_level.load()); }

void log_message(LogLevel level, const std::string& msg) {
    if (static_cast<int>(level) < g_level) return;
    static const char* prefix[] = {"debug: ", "", "warning: ", "error: "};
    std::lock_guard<std::mutex> lock(g_mutex);
    std::fprintf(stderr, "%s%s\n", prefix[static_cast<int>(level)], msg.c_str());
    std::fflush(stderr);
}

void log_once(LogLevel level, const std::string& msg) {
    static std::mutex once_mutex;
    static std::set<std::string> seen;
    {
        std::lock_guard<std::mutex> lock(once_mutex);
        if (!seen.insert(msg).second) return;
    }
    log_message(level, msg);
}

void check_failed(const char* expr, const char* file, int line, const std::string& msg) {
    std::ostringstream s;
    s << file << ":" << line << ": CHECK(" << expr << ") failed";
    if (!msg.empty()) s << ": " << msg;
    throw InternalError(s.str());
}

}  // namespace penumbra
