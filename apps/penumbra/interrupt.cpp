#include "apps/penumbra/interrupt.h"

#include <csignal>

namespace penumbra {

namespace {

// A signal handler can reach nothing but globals; this is the only one. Lock-free, so
// incrementing it is async-signal-safe.
std::atomic<int> g_sigint_count{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction g_previous {};

extern "C" void on_sigint(int) { g_sigint_count.fetch_add(1, std::memory_order_relaxed); }

}  // namespace

InterruptScope::InterruptScope() {
    g_sigint_count = 0;
    struct sigaction sa {};
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    // SA_RESTART: a signal during a file write must not turn into a failed write.
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, &g_previous);
}

InterruptScope::~InterruptScope() { sigaction(SIGINT, &g_previous, nullptr); }

const std::atomic<int>& InterruptScope::count() const { return g_sigint_count; }

}  // namespace penumbra
