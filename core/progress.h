// One thread-safe progress reporter, updated once per finished tile. On a terminal it
// redraws a bar with ETA and throughput; otherwise it prints a plain line every few
// seconds, which reads well in CI and batch logs.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace penumbra {

class ProgressReporter {
public:
    // total: units of work (e.g. pixel samples); unit: what the throughput counts.
    ProgressReporter(std::string label, uint64_t total, std::string unit, bool enabled = true);
    ~ProgressReporter();
    void update(uint64_t done_units);  // adds done_units
    void done();
    double elapsed_seconds() const;

private:
    void print_locked(bool final);
    std::string m_label, m_unit;
    uint64_t m_total, m_done = 0;
    bool m_enabled, m_tty, m_finished = false;
    std::chrono::steady_clock::time_point m_start, m_last_print;
    std::mutex m_mutex;
};

// Peak resident memory of this process so far, in bytes.
uint64_t peak_memory_bytes();
// "1.23 GiB"-style text.
std::string format_bytes(uint64_t bytes);
// "1m 23s"-style text.
std::string format_duration(double seconds);

}  // namespace penumbra
