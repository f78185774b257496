// Ctrl-C or SIGTERM during a render (Slurm sends SIGTERM on preemption and at a time
// limit): the first signal asks the render to stop after its current pass and write a
// partial image and a checkpoint; the second abandons the pass without writing. The
// handler only counts signals in an atomic; the render loop polls the count.
#pragma once

#include <atomic>

namespace penumbra {

// Installs the SIGINT and SIGTERM handler for its lifetime and restores the previous
// ones after.
class InterruptScope {
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;
    const std::atomic<int>& count() const;
    int signals() const { return count().load(); }
    // The exit status a shell reports for a command the last signal stopped: 130 after
    // SIGINT, 143 after SIGTERM; 0 when none came.
    int exit_status() const;
};

}  // namespace penumbra
