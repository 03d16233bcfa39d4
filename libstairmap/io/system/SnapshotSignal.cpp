#include "io/system/SnapshotSignal.h"

#include <atomic>
#include <csignal>

namespace stairmap::io {
namespace {

// Lock-free, so setting it from a signal handler is safe; exchange() never loses a signal that
// arrives between reading and clearing.
std::atomic<bool> g_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "signal flag must be lock-free");
struct sigaction g_previous_usr1 {};

extern "C" void recordSnapshotRequest(int) { g_requested.store(true); }

}  // namespace

SnapshotSignal::SnapshotSignal() {
    g_requested = false;
    struct sigaction action {};
    action.sa_handler = recordSnapshotRequest;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGUSR1, &action, &g_previous_usr1);
}

SnapshotSignal::~SnapshotSignal() { sigaction(SIGUSR1, &g_previous_usr1, nullptr); }

bool SnapshotSignal::take() { return g_requested.exchange(false); }

}  // namespace stairmap::io
