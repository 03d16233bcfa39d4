#include "live/LatencyStats.h"

#include <gtest/gtest.h>

#include <random>

namespace stairmap::live {
namespace {

TEST(LatencyStats, EmptyGivesZeros) {
    const LatencySummary s = LatencyStats().summary();
    EXPECT_EQ(s.count, 0u);
    EXPECT_EQ(s.median_s, 0.0);
    EXPECT_EQ(s.p95_s, 0.0);
}

TEST(LatencyStats, ExactWhileEverySampleIsKept) {
    LatencyStats stats(256);
    for (int i = 100; i >= 1; --i) stats.add(i * 0.001);  // 1..100 ms, in reverse order
    const LatencySummary s = stats.summary();
    EXPECT_EQ(s.count, 100u);
    EXPECT_DOUBLE_EQ(s.median_s, 0.050);  // nearest rank: the 50th of 100
    EXPECT_DOUBLE_EQ(s.p95_s, 0.095);
    EXPECT_NEAR(s.mean_s, 0.0505, 1e-12);
    EXPECT_DOUBLE_EQ(s.max_s, 0.100);
}

TEST(LatencyStats, LongStreamKeepsFixedMemoryAndAccurateQuantiles) {
    // Exponential durations with mean 20 ms: median 20 ln 2 = 13.86 ms, p95 20 ln 20 = 59.9 ms.
    LatencyStats stats(4096);
    std::mt19937 rng(7);
    std::exponential_distribution<double> draw(1.0 / 0.020);
    for (int i = 0; i < 1000000; ++i) stats.add(draw(rng));
    EXPECT_EQ(stats.kept(), 4096u);
    EXPECT_EQ(stats.count(), 1000000u);
    const LatencySummary s = stats.summary();
    EXPECT_NEAR(s.median_s, 0.020 * std::log(2.0), 0.0015);
    EXPECT_NEAR(s.p95_s, 0.020 * std::log(20.0), 0.004);
    EXPECT_NEAR(s.mean_s, 0.020, 0.0002);
}

TEST(LatencyStats, ReservoirFollowsAShiftInTheStream) {
    // 1000 fast values then 9000 slow ones: a uniform sample must be ~90 % slow, so the median
    // is slow; a sample that kept only the first values would say fast.
    LatencyStats stats(512);
    for (int i = 0; i < 1000; ++i) stats.add(0.001);
    for (int i = 0; i < 9000; ++i) stats.add(0.100);
    EXPECT_DOUBLE_EQ(stats.quantile(0.5), 0.100);
    EXPECT_DOUBLE_EQ(stats.quantile(0.0), 0.001);
}

}  // namespace
}  // namespace stairmap::live
