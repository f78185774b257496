// Ctrl-C during a render: the first SIGINT asks the render to stop after its current
// pass and write a partial image; the second abandons the pass without writing. The
// handler only counts signals in an atomic; the render loop polls the count.
#pragma once

#include <atomic>

namespace penumbra {

// Installs the SIGINT handler for its lifetime and restores the previous one after.
class InterruptScope {
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;
    const std::atomic<int>& count() const;
    int signals() const { return count().load(); }
};

}  // namespace penumbra
