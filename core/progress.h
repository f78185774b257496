// One thread-safe progress reporter per image, updated once per finished tile, and an
// optional overall bar for a batch. On a terminal both redraw in place (image bar above,
// batch bar below) with ETA and throughput; otherwise a plain line every few seconds,
// which reads well in CI and batch logs.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace penumbra {

// The whole batch: images finished, the rays they traced, and the time since it began.
// Fed by the app between images; drawn by the current image's ProgressReporter.
class BatchProgress {
public:
    BatchProgress(size_t jobs, bool enabled);
    void job_finished(uint64_t rays);  // also for failed and skipped jobs
    size_t jobs() const { return m_jobs; }
    size_t jobs_done() const;
    bool enabled() const { return m_enabled; }
    // The overall bar or line, given how far the current image is and its rays so far
    // (counted rays_age seconds ago).
    std::string describe(double current_fraction, uint64_t current_rays, double rays_age,
                         bool tty) const;

private:
    friend class ProgressReporter;
    size_t m_jobs, m_done = 0;
    uint64_t m_rays = 0;
    bool m_enabled;
    bool m_bar_on_screen = false;  // the terminal shows the two-line block
    std::chrono::steady_clock::time_point m_start;
    mutable std::mutex m_mutex;
};

class ProgressReporter {
public:
    // total: units of work (e.g. pixel samples); unit: what the throughput counts.
    ProgressReporter(std::string label, uint64_t total, std::string unit, bool enabled = true,
                     BatchProgress* batch = nullptr);
    ~ProgressReporter();
    void update(uint64_t done_units);  // adds done_units
    // With a time limit, the fraction done is the larger of work and time.
    void set_time_limit(double seconds);
    // Rays traced so far (set between passes, when counting them is safe): the
    // throughput is then shown in rays/s.
    void set_rays(uint64_t rays);
    void done();
    double elapsed_seconds() const;

private:
    void print_locked(bool final);
    std::string m_label, m_unit;
    uint64_t m_total, m_done = 0, m_rays = 0;
    double m_time_limit = 0, m_rays_seconds = 0;
    bool m_enabled, m_tty, m_finished = false;
    BatchProgress* m_batch;
    std::chrono::steady_clock::time_point m_start, m_last_print;
    std::mutex m_mutex;
};

// Peak resident memory of this process so far, in bytes.
uint64_t peak_memory_bytes();
// CPU time (user + system, all threads) of this process so far, in seconds.
double process_cpu_seconds();
// "1.23 GiB"-style text.
std::string format_bytes(uint64_t bytes);
// "1m 23s"-style text.
std::string format_duration(double seconds);
// "3.21M"-style text for rates and counts.
std::string format_count(double value);

}  // namespace penumbra
