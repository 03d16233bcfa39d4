#include "live/ScanQueue.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace stairmap::live {
namespace {

using namespace std::chrono_literals;

Scan scanAt(double stamp_s) {
    Scan s;
    s.stamp_s = stamp_s;
    return s;
}

TEST(ScanQueue, LossyDropsTheOldestWhenFull) {
    std::atomic<bool> stop{false};
    ScanQueue q({2, true}, stop);
    for (double t : {1.0, 2.0, 3.0, 4.0}) q.push(scanAt(t));  // never blocks
    const ScanQueueCounters c = q.counters();
    EXPECT_EQ(c.pushed, 4u);
    EXPECT_EQ(c.dropped, 2u);
    EXPECT_EQ(c.queued, 2u);
    EXPECT_DOUBLE_EQ(c.newest_stamp_s, 4.0);
    EXPECT_DOUBLE_EQ(q.pop(0ms)->scan.stamp_s, 3.0);  // 1 and 2 were the oldest
    EXPECT_DOUBLE_EQ(q.pop(0ms)->scan.stamp_s, 4.0);
    EXPECT_FALSE(q.pop(0ms).has_value());
}

TEST(ScanQueue, LosslessBlocksThePusherUntilThereIsRoom) {
    std::atomic<bool> stop{false};
    ScanQueue q({1, false}, stop);
    q.push(scanAt(1.0));
    std::atomic<bool> second_pushed{false};
    std::thread pusher([&] {
        q.push(scanAt(2.0));
        second_pushed = true;
    });
    std::this_thread::sleep_for(150ms);
    EXPECT_FALSE(second_pushed.load()) << "a full lossless queue must block the pusher";
    EXPECT_DOUBLE_EQ(q.pop(0ms)->scan.stamp_s, 1.0);
    const auto item = q.pop(2000ms);  // the blocked push lands now
    pusher.join();
    ASSERT_TRUE(item.has_value());
    EXPECT_DOUBLE_EQ(item->scan.stamp_s, 2.0);
    EXPECT_TRUE(second_pushed.load());
    EXPECT_EQ(q.counters().dropped, 0u);
}

TEST(ScanQueue, LosslessPushGivesUpWhenStopIsRequested) {
    std::atomic<bool> stop{false};
    ScanQueue q({1, false}, stop);
    q.push(scanAt(1.0));
    std::thread pusher([&] { q.push(scanAt(2.0)); });
    std::this_thread::sleep_for(50ms);
    const auto t0 = std::chrono::steady_clock::now();
    stop = true;
    q.wake();
    pusher.join();
    EXPECT_LT(std::chrono::steady_clock::now() - t0, 1s);
    EXPECT_EQ(q.counters().discarded_on_stop, 1u);
    EXPECT_EQ(q.counters().queued, 1u);
}

TEST(ScanQueue, CloseHandsOutWhatIsQueuedThenReportsDrained) {
    std::atomic<bool> stop{false};
    ScanQueue q({4, false}, stop);
    q.push(scanAt(1.0));
    q.close();
    EXPECT_FALSE(q.drained());
    EXPECT_DOUBLE_EQ(q.pop(0ms)->scan.stamp_s, 1.0);
    EXPECT_TRUE(q.drained());
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_FALSE(q.pop(5000ms).has_value());  // closed and empty: no wait
    EXPECT_LT(std::chrono::steady_clock::now() - t0, 1s);
}

TEST(ScanQueue, RecordsEachScansArrivalAtPush) {
    std::atomic<bool> stop{false};
    ScanQueue q({4, true}, stop);
    const auto before = std::chrono::steady_clock::now();
    q.push(scanAt(1.0));
    const auto after = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(30ms);
    const auto item = q.pop(0ms);
    ASSERT_TRUE(item.has_value());
    EXPECT_GE(item->arrival, before);
    EXPECT_LE(item->arrival, after);
}

TEST(ScanQueue, PeakQueuedNeverExceedsCapacity) {
    std::atomic<bool> stop{false};
    ScanQueue q({3, true}, stop);
    for (int i = 0; i < 1000; ++i) q.push(scanAt(i));
    EXPECT_EQ(q.counters().peak_queued, 3u);
    EXPECT_EQ(q.counters().dropped, 997u);
}

TEST(ScanQueue, ZeroCapacityIsRejected) {
    std::atomic<bool> stop{false};
    EXPECT_THROW(ScanQueue({0, true}, stop), std::invalid_argument);
}

}  // namespace
}  // namespace stairmap::live
