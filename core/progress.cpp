#include "core/progress.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace penumbra {

ProgressReporter::ProgressReporter(std::string label, uint64_t total, std::string unit,
                                   bool enabled)
    : m_label(std::move(label)),
      m_unit(std::move(unit)),
      m_total(total),
      m_enabled(enabled),
      m_tty(isatty(fileno(stderr)) != 0),
      m_start(std::chrono::steady_clock::now()),
      m_last_print(m_start) {}

ProgressReporter::~ProgressReporter() { done(); }

double ProgressReporter::elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

void ProgressReporter::update(uint64_t units) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_done += units;
    if (!m_enabled || m_finished) return;
    const auto now = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - m_last_print).count();
    // Redraw a terminal bar often; write a log line only every 5 seconds.
    if (since >= (m_tty ? 0.1 : 5.0)) {
        m_last_print = now;
        print_locked(false);
    }
}

void ProgressReporter::done() {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_finished) return;
    m_finished = true;
    if (m_enabled) print_locked(true);
}

void ProgressReporter::print_locked(bool final) {
    const double t = elapsed_seconds();
    const double frac = m_total ? double(m_done) / double(m_total) : 1.0;
    const double rate = t > 0 ? m_done / t : 0;
    const double eta = rate > 0 ? (m_total - m_done) / rate : 0;
    char rate_text[32];
    if (rate >= 1e6)
        std::snprintf(rate_text, sizeof rate_text, "%.2fM", rate / 1e6);
    else if (rate >= 1e3)
        std::snprintf(rate_text, sizeof rate_text, "%.1fk", rate / 1e3);
    else
        std::snprintf(rate_text, sizeof rate_text, "%.0f", rate);
    if (m_tty) {
        constexpr int kWidth = 30;
        const int filled = static_cast<int>(frac * kWidth);
        std::string bar(filled, '=');
        if (filled < kWidth) bar += '>' + std::string(kWidth - filled - 1, ' ');
        std::fprintf(stderr, "\r%s [%s] %5.1f%%  %s  ETA %s  %s %s/s\x1b[K", m_label.c_str(),
                     bar.c_str(), 100 * frac, format_duration(t).c_str(),
                     final ? "0s" : format_duration(eta).c_str(), rate_text, m_unit.c_str());
        if (final) std::fputc('\n', stderr);
    } else {
        std::fprintf(stderr, "%s: %.1f%% done, %s elapsed, ETA %s, %s %s/s\n", m_label.c_str(),
                     100 * frac, format_duration(t).c_str(),
                     final ? "0s" : format_duration(eta).c_str(), rate_text, m_unit.c_str());
    }
    std::fflush(stderr);
}

uint64_t peak_memory_bytes() {
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<uint64_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

std::string format_bytes(uint64_t bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    double v = static_cast<double>(bytes);
    int u = 0;
    while (v >= 1024 && u < 4) {
        v /= 1024;
        ++u;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.2f %s", v, units[u]);
    return buf;
}

std::string format_duration(double s) {
    char buf[32];
    if (!std::isfinite(s)) return "?";
    if (s < 10)
        std::snprintf(buf, sizeof buf, "%.2fs", s);
    else if (s < 60)
        std::snprintf(buf, sizeof buf, "%.0fs", s);
    else if (s < 3600)
        std::snprintf(buf, sizeof buf, "%dm %02ds", int(s) / 60, int(s) % 60);
    else
        std::snprintf(buf, sizeof buf, "%dh %02dm", int(s) / 3600, (int(s) / 60) % 60);
    return buf;
}

}  // namespace penumbra
