// SIGUSR1 as a snapshot request: recorded, read once, previous handler restored.
#include "io/system/SnapshotSignal.h"

#include <gtest/gtest.h>

#include <csignal>

namespace stairmap::io {
namespace {

volatile std::sig_atomic_t g_custom_usr1 = 0;
extern "C" void customUsr1Handler(int) { g_custom_usr1 = 1; }

TEST(SnapshotSignal, EachSignalIsTakenOnceAndThePreviousHandlerComesBack) {
    std::signal(SIGUSR1, customUsr1Handler);
    {
        SnapshotSignal snapshot;
        EXPECT_FALSE(snapshot.take());
        std::raise(SIGUSR1);
        std::raise(SIGUSR1);  // two before a take: one snapshot
        EXPECT_TRUE(snapshot.take());
        EXPECT_FALSE(snapshot.take());
        std::raise(SIGUSR1);
        EXPECT_TRUE(snapshot.take());
        EXPECT_EQ(g_custom_usr1, 0) << "the custom handler must not run while the object lives";
    }
    std::raise(SIGUSR1);
    EXPECT_EQ(g_custom_usr1, 1);
    std::signal(SIGUSR1, SIG_DFL);
}

}  // namespace
}  // namespace stairmap::io
