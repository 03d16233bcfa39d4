// SIGINT/SIGTERM as a stop request: the first is recorded, a second ends the process.
#include "io/system/StopSignals.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

namespace stairmap::io {
namespace {

volatile std::sig_atomic_t g_custom = 0;
extern "C" void customHandler(int) { g_custom = 1; }

TEST(StopSignals, FirstSignalIsRecordedAndPreviousHandlersComeBack) {
    std::signal(SIGTERM, customHandler);
    {
        const StopSignals stop;
        EXPECT_EQ(stop.received(), 0);
        std::raise(SIGINT);
        EXPECT_EQ(stop.received(), SIGINT);  // and we are still running
    }
    std::raise(SIGTERM);
    EXPECT_EQ(g_custom, 1);
    std::signal(SIGTERM, SIG_DFL);
}

TEST(StopSignals, SecondSignalEndsTheProcess) {
    const pid_t child = ::fork();
    if (child == 0) {
        const StopSignals stop;
        std::raise(SIGTERM);
        if (stop.received() != SIGTERM) ::_exit(3);
        std::raise(SIGTERM);
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
}

}  // namespace
}  // namespace stairmap::io
