#include "io/system/StopSignals.h"

#include <csignal>

namespace stairmap::io {
namespace {

volatile std::sig_atomic_t g_received = 0;
struct sigaction g_previous_int {
}, g_previous_term{};

extern "C" void recordSignal(int signal) { g_received = signal; }

}  // namespace

StopSignals::StopSignals() {
    g_received = 0;
    struct sigaction action {};
    action.sa_handler = recordSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART | SA_RESETHAND;  // a second signal takes the default action
    sigaction(SIGINT, &action, &g_previous_int);
    sigaction(SIGTERM, &action, &g_previous_term);
}

StopSignals::~StopSignals() {
    sigaction(SIGINT, &g_previous_int, nullptr);
    sigaction(SIGTERM, &g_previous_term, nullptr);
}

int StopSignals::received() const { return g_received; }

}  // namespace stairmap::io
