#include "apps/penumbra/interrupt.h"

#include <csignal>

namespace penumbra {

namespace {

// A signal handler can reach nothing but globals; these are the only ones. Lock-free,
// so storing to them is async-signal-safe.
std::atomic<int> g_signal_count{0};
std::atomic<int> g_last_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction g_previous_int {};
struct sigaction g_previous_term {};

extern "C" void on_signal(int sig) {
    g_last_signal.store(sig, std::memory_order_relaxed);
    g_signal_count.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

InterruptScope::InterruptScope() {
    g_signal_count = 0;
    g_last_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    // SA_RESTART: a signal during a file write must not turn into a failed write.
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, &g_previous_int);
    sigaction(SIGTERM, &sa, &g_previous_term);
}

InterruptScope::~InterruptScope() {
    sigaction(SIGINT, &g_previous_int, nullptr);
    sigaction(SIGTERM, &g_previous_term, nullptr);
}

const std::atomic<int>& InterruptScope::count() const { return g_signal_count; }

int InterruptScope::exit_status() const {
    const int sig = g_last_signal.load();
    return sig ? 128 + sig : 0;
}

}  // namespace penumbra
