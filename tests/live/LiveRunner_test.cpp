#include "live/LiveRunner.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <thread>

#include "sim/ScanSimulator.h"
#include "sim/SensorModel.h"
#include "sim/StairGenerators.h"

namespace stairmap::live {
namespace {

using namespace std::chrono_literals;

/// Scans of a robot driving at 10 Hz towards one 8-riser flight (rise 0.17 m) 4 m ahead.
std::vector<Scan> stairDrive(int num_scans) {
    sim::Scene scene;
    sim::addFloor(scene, {-10, -10}, {10, 10}, 0.0);
    sim::StraightStairParams stair;
    stair.origin = Eigen::Vector3d(3, 0, 0);
    sim::addStraightStair(scene, stair);
    sim::SensorParams sensor = sim::vlp16();
    sensor.horizontal_resolution_deg = 0.4;
    std::mt19937 rng(5);
    std::vector<Scan> scans;
    for (int i = 0; i < num_scans; ++i) {
        Scan scan;
        scan.index = i;
        scan.stamp_s = 100.0 + 0.1 * i;
        scan.T_world_robot.translation() = Eigen::Vector3d(-1.0 + 0.1 * i, 0.0, 0.35);
        scan.points_robot = sim::simulateScan(scene, scan.T_world_robot, sensor, rng, 0.1 * i);
        scans.push_back(std::move(scan));
    }
    return scans;
}

/// Pushes its scans (repeating them with later stamps when `endless`) and counts them.
class FakeSource : public LiveSource {
public:
    FakeSource(std::vector<Scan> scans, bool lossy, bool endless = false)
        : scans_(std::move(scans)), lossy_(lossy), endless_(endless) {}
    void run(ScanSink& sink, const std::atomic<bool>& stop) override {
        for (std::size_t i = 0; !stop; ++i) {
            if (i >= scans_.size() && !endless_) break;
            Scan s = scans_[i % scans_.size()];
            s.stamp_s += 1000.0 * (i / scans_.size());
            sink.push(std::move(s));
            ++pushed_;
            if (throw_after_ > 0 && pushed_ == throw_after_)
                throw std::runtime_error("fake: the file vanished");
        }
    }
    bool lossy() const override { return lossy_; }
    std::string describe() const override { return "fake"; }
    std::map<std::string, std::size_t> counters() const override {
        return {{"pushed", pushed_.load()}};
    }
    std::atomic<std::size_t> pushed_{0};
    std::size_t throw_after_ = 0;

private:
    std::vector<Scan> scans_;
    bool lossy_, endless_;
};

struct RecordingListener : LandmarkListener {
    void onLandmarks(const LandmarkMap& landmarks, double stamp_s) override {
        calls.emplace_back(landmarks.staircases().size(), stamp_s);
    }
    std::vector<std::pair<std::size_t, double>> calls;
};

TEST(LiveRunner, LosslessSourceHasEveryScanMappedInOrderAndHearsOfEachChange) {
    FakeSource source(stairDrive(30), /*lossy=*/false);
    pipeline::Mapper mapper{pipeline::MapperParams{}};
    LiveRunner runner(mapper, source, {});
    RecordingListener listener;
    runner.addListener(listener);
    EXPECT_EQ(runner.run(), LiveEnd::SourceEnded);
    const LiveStatus s = runner.status();
    EXPECT_EQ(s.scans_mapped, 30u);
    EXPECT_EQ(s.queue.dropped, 0u);
    EXPECT_LE(s.queue.peak_queued, 4u);
    EXPECT_DOUBLE_EQ(s.last_stamp_s, 100.0 + 0.1 * 29);
    ASSERT_GE(listener.calls.size(), 2u) << "once at the start, then on each change";
    EXPECT_EQ(listener.calls.front(), std::make_pair(std::size_t(0), 0.0));
    EXPECT_GE(mapper.landmarks().staircases().size(), 1u) << "the flight must have been mapped";
    EXPECT_EQ(s.landmark_changes, listener.calls.size() - 1);
    EXPECT_GT(listener.calls.back().second, 100.0);  // stamped with the scan that caused it
    EXPECT_EQ(s.update_latency.count, s.landmark_changes);
    EXPECT_EQ(s.scan_latency.count, 30u);
    EXPECT_GT(s.update_latency.median_s, 0.0);
    EXPECT_GE(s.update_latency.max_s, s.update_latency.median_s);
    EXPECT_GT(s.processing.max_s, 0.0);
}

TEST(LiveRunner, LossySourceFasterThanTheMapperLosesTheOldestAndCountsThem) {
    FakeSource source(stairDrive(5), /*lossy=*/true, /*endless=*/true);
    pipeline::Mapper mapper{pipeline::MapperParams{}};
    LiveRunnerParams params;
    params.max_scans = 20;
    params.queue_capacity = 3;
    LiveRunner runner(mapper, source, params);
    runner.setStopCheck([] {
        std::this_thread::sleep_for(5ms);  // a slow mapper: the source pushes without pause
        return false;
    });
    EXPECT_EQ(runner.run(), LiveEnd::MaxScans);
    const LiveStatus s = runner.status();
    EXPECT_EQ(s.scans_mapped, 20u);
    EXPECT_GT(s.queue.dropped, 0u);
    EXPECT_LE(s.queue.peak_queued, 3u);
    // Every pushed scan is mapped, dropped, or still queued when the run ended.
    EXPECT_EQ(s.queue.pushed, s.scans_mapped + s.queue.dropped + s.queue.queued);
}

TEST(LiveRunner, DurationAndStopCheckEndAnEndlessStream) {
    const std::vector<Scan> scans = stairDrive(3);
    {
        FakeSource source(scans, true, true);
        pipeline::Mapper mapper{pipeline::MapperParams{}};
        LiveRunnerParams params;
        params.duration_s = 0.3;
        LiveRunner runner(mapper, source, params);
        const auto t0 = std::chrono::steady_clock::now();
        EXPECT_EQ(runner.run(), LiveEnd::Duration);
        EXPECT_LT(std::chrono::steady_clock::now() - t0, 3s);
    }
    {
        FakeSource source(scans, false, true);
        pipeline::Mapper mapper{pipeline::MapperParams{}};
        LiveRunner runner(mapper, source, {});
        runner.setStopCheck([&] { return mapper.stats().scans >= 4; });
        EXPECT_EQ(runner.run(), LiveEnd::StopRequested);
        EXPECT_EQ(mapper.stats().scans, 4u) << "the scan in hand is finished, no more";
    }
}

TEST(LiveRunner, ASourceThatFailsEndsTheRunWithItsErrorAfterItsScansAreMapped) {
    FakeSource source(stairDrive(6), false);
    source.throw_after_ = 4;
    pipeline::Mapper mapper{pipeline::MapperParams{}};
    LiveRunner runner(mapper, source, {});
    EXPECT_EQ(runner.run(), LiveEnd::SourceEnded);
    ASSERT_TRUE(runner.sourceError().has_value());
    EXPECT_NE(runner.sourceError()->find("the file vanished"), std::string::npos);
    EXPECT_EQ(mapper.stats().scans, 4u);
}

TEST(LiveRunner, TickRunsPeriodicallyAndOnceAtTheEnd) {
    FakeSource source(stairDrive(3), false, true);
    pipeline::Mapper mapper{pipeline::MapperParams{}};
    LiveRunnerParams params;
    params.duration_s = 0.5;
    params.tick_period_s = 0.1;
    LiveRunner runner(mapper, source, params);
    std::vector<LiveStatus> ticks;
    runner.setTickCallback([&](const LiveStatus& s) { ticks.push_back(s); });
    runner.run();
    EXPECT_GE(ticks.size(), 3u);
    EXPECT_LE(ticks.size(), 8u);
    EXPECT_EQ(ticks.back().scans_mapped, mapper.stats().scans);
    EXPECT_EQ(ticks.back().source_counters.at("pushed"), source.pushed_.load());
}

struct ThrowingListener : LandmarkListener {
    void onLandmarks(const LandmarkMap&, double stamp_s) override {
        if (stamp_s > 0) throw std::runtime_error("landmarks.json: No space left on device");
    }
};

TEST(LiveRunner, AFailingListenerStopsTheSourceAndPropagatesInsteadOfTerminating) {
    FakeSource source(stairDrive(30), false, /*endless=*/true);
    pipeline::Mapper mapper{pipeline::MapperParams{}};
    LiveRunner runner(mapper, source, {});
    ThrowingListener listener;
    runner.addListener(listener);
    EXPECT_THROW(runner.run(), std::runtime_error);  // the source thread was joined: no terminate
    const std::size_t pushed = source.pushed_.load();
    std::this_thread::sleep_for(50ms);
    EXPECT_EQ(source.pushed_.load(), pushed) << "the source must have stopped";
}

}  // namespace
}  // namespace stairmap::live
