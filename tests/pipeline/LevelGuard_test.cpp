#include "pipeline/LevelGuard.h"

#include <gtest/gtest.h>

namespace stairmap::pipeline {
namespace {

TEST(LevelGuard, FlatDriveIsLevel) {
    LevelGuard guard(10.0);
    for (int i = 0; i < 50; ++i) EXPECT_TRUE(guard.update({0.1 * i, 0.0, 0.35}));
}

TEST(LevelGuard, ClimbingAFlightIsNotLevelAndLevelAgainAtTheTop) {
    LevelGuard guard(10.0);
    for (int i = 0; i < 10; ++i) guard.update({0.1 * i, 0, 0.35});
    bool saw_climb = false;
    // 34 deg flight (rise 0.19 / run 0.28) sampled every 0.1 m of run.
    for (int i = 1; i <= 30; ++i) saw_climb |= !guard.update({0.9 + 0.1 * i, 0, 0.35 + 0.068 * i});
    EXPECT_TRUE(saw_climb);
    EXPECT_FALSE(guard.update({4.0, 0, 2.39}));  // still on the flight
    bool level_again = false;
    for (int i = 1; i <= 15; ++i) level_again = guard.update({4.0 + 0.1 * i, 0, 2.39});
    EXPECT_TRUE(level_again);
}

TEST(LevelGuard, StandingStillKeepsTheLastState) {
    LevelGuard guard(10.0);
    EXPECT_TRUE(guard.update({0, 0, 0}));
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(guard.update({0, 0, 0.001 * i}));  // pose jitter
}

TEST(LevelGuard, GentleRampBelowThresholdIsLevel) {
    LevelGuard guard(10.0);
    for (int i = 0; i < 40; ++i) EXPECT_TRUE(guard.update({0.1 * i, 0, 0.1 * i * 0.1}));  // 5.7 deg
}

TEST(LevelGuard, DisabledGuardIsAlwaysLevel) {
    LevelGuard guard(0.0);
    for (int i = 0; i < 10; ++i) EXPECT_TRUE(guard.update({0.1 * i, 0, 0.5 * i}));
}

TEST(LevelGuard, InvalidSlopeThrows) { EXPECT_THROW(LevelGuard(95.0), std::invalid_argument); }

}  // namespace
}  // namespace stairmap::pipeline
