#include "core/progress.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace penumbra {

namespace {

std::string bar(double fraction) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kWidth);
    std::string b(filled, '=');
    if (filled < kWidth) b += '>' + std::string(kWidth - filled - 1, ' ');
    return "[" + b + "]";
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

BatchProgress::BatchProgress(size_t jobs, bool enabled)
    : m_jobs(jobs), m_enabled(enabled), m_start(std::chrono::steady_clock::now()) {}

void BatchProgress::job_finished(uint64_t rays) {
    std::lock_guard<std::mutex> lock(m_mutex);
    ++m_done;
    m_rays += rays;
}

size_t BatchProgress::jobs_done() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_done;
}

std::string BatchProgress::describe(double current_fraction, uint64_t current_rays,
                                    double rays_age, bool tty) const {
    std::lock_guard<std::mutex> lock(m_mutex);
    const double t = seconds_since(m_start);
    // The current image's rays were counted rays_age ago: rate over the time up to then.
    const double rays_t = t - rays_age;
    const double frac =
        m_jobs ? std::min(1.0, (m_done + std::clamp(current_fraction, 0.0, 1.0)) / m_jobs) : 1;
    // Assumes the remaining images cost what the finished ones did on average.
    const double eta = frac > 0 ? t * (1 - frac) / frac : NAN;
    const std::string rate = format_count(rays_t > 0 ? (m_rays + current_rays) / rays_t : 0);
    char buf[160];
    if (tty)
        std::snprintf(buf, sizeof buf, "batch %zu/%zu %s %5.1f%%  %s  ETA %s  %s rays/s",
                      std::min(m_done + 1, m_jobs), m_jobs, bar(frac).c_str(), 100 * frac,
                      format_duration(t).c_str(), format_duration(eta).c_str(), rate.c_str());
    else
        std::snprintf(buf, sizeof buf, "batch: %zu of %zu images done, %.1f%%, ETA %s, %s rays/s",
                      m_done, m_jobs, 100 * frac, format_duration(eta).c_str(), rate.c_str());
    return buf;
}

ProgressReporter::ProgressReporter(std::string label, uint64_t total, std::string unit,
                                   bool enabled, BatchProgress* batch)
    : m_label(std::move(label)),
      m_unit(std::move(unit)),
      m_total(total),
      m_enabled(enabled),
      m_tty(isatty(fileno(stderr)) != 0),
      m_batch(batch && batch->enabled() ? batch : nullptr),
      m_start(std::chrono::steady_clock::now()),
      m_last_print(m_start) {
    // A log says when each image began; a terminal shows the bar at the first update.
    if (m_enabled && !m_tty) {
        std::fprintf(stderr, "%s: started, %s %s to do\n", m_label.c_str(),
                     format_count(double(m_total)).c_str(), m_unit.c_str());
        std::fflush(stderr);
    }
}

ProgressReporter::~ProgressReporter() { done(); }

double ProgressReporter::elapsed_seconds() const { return seconds_since(m_start); }

void ProgressReporter::set_time_limit(double seconds) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_time_limit = seconds;
}

void ProgressReporter::set_rays(uint64_t rays) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_rays = rays;
    m_rays_seconds = elapsed_seconds();
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
    double frac = m_total ? double(m_done) / double(m_total) : 1.0;
    const double rate = t > 0 ? m_done / t : 0;
    double eta = rate > 0 ? (m_total - m_done) / rate : NAN;
    if (m_time_limit > 0) {
        frac = std::max(frac, t / m_time_limit);
        eta = std::min(std::isfinite(eta) ? eta : m_time_limit, std::max(0.0, m_time_limit - t));
    }
    frac = std::min(frac, 1.0);
    if (final) eta = 0;
    // Rays are only counted between passes; before the first count, show the units.
    const bool show_rays = m_rays_seconds > 0;
    const std::string rate_text =
        format_count(show_rays ? m_rays / m_rays_seconds : rate) + " " +
        (show_rays ? std::string("rays") : m_unit) + "/s";
    const std::string batch =
        m_batch ? m_batch->describe(final ? 1.0 : frac, m_rays,
                                    show_rays ? t - m_rays_seconds : 0, m_tty)
                : std::string();
    std::string out;
    if (m_tty) {
        char line[256];
        std::snprintf(line, sizeof line, "%s %s %5.1f%%  %s  ETA %s  %s", m_label.c_str(),
                      bar(frac).c_str(), 100 * frac, format_duration(t).c_str(),
                      format_duration(eta).c_str(), rate_text.c_str());
        out = "\r";
        if (m_batch) {
            std::lock_guard<std::mutex> lock(m_batch->m_mutex);
            if (m_batch->m_bar_on_screen) out += "\x1b[1A";
            // The final image line stays; the batch bar is wiped until the next image.
            m_batch->m_bar_on_screen = !final;
        }
        out += line + std::string("\x1b[K");
        if (m_batch) out += "\n" + (final ? std::string() : batch) + "\x1b[K";
        else if (final) out += "\n";
    } else {
        char line[256];
        std::snprintf(line, sizeof line, "%s: %.1f%% done, %s elapsed, ETA %s, %s",
                      m_label.c_str(), 100 * frac, format_duration(t).c_str(),
                      format_duration(eta).c_str(), rate_text.c_str());
        out = line + (m_batch ? " | " + batch : std::string()) + "\n";
    }
    std::fputs(out.c_str(), stderr);
    std::fflush(stderr);
}

uint64_t peak_memory_bytes() {
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<uint64_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

double process_cpu_seconds() {
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
           1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
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

std::string format_count(double v) {
    char buf[32];
    if (!std::isfinite(v)) return "?";
    if (v >= 1e9)
        std::snprintf(buf, sizeof buf, "%.2fG", v / 1e9);
    else if (v >= 1e6)
        std::snprintf(buf, sizeof buf, "%.2fM", v / 1e6);
    else if (v >= 1e3)
        std::snprintf(buf, sizeof buf, "%.1fk", v / 1e3);
    else
        std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

}  // namespace penumbra
