// A followed file: reads wait for the writer at the end of the data (a half-written object is read
// whole once its tail arrives), end on idle timeout or stop; a growing TUM file's poses are read
// as complete lines appear, and a query waits for the pose it needs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "io/follow/GrowingFileStream.h"
#include "io/follow/GrowingTrajectory.h"

namespace stairmap::io {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

std::string scratch(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "growing_file";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::trunc).flush();
    return path;
}

void append(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::app | std::ios::binary) << text << std::flush;
}

TEST(GrowingFileStream, AReadAtTheEndWaitsForTheWriterToCompleteIt) {
    const std::string path = scratch("wait.bin");
    append(path, "abc");
    std::atomic<bool> stop{false};
    GrowingFileStream stream(path, {5.0, 0.01}, stop);
    std::thread writer([&] {
        std::this_thread::sleep_for(150ms);
        append(path, "de");
        std::this_thread::sleep_for(150ms);
        append(path, "fgh");
    });
    char buf[6] = {};
    const auto t0 = Clock::now();
    EXPECT_EQ(stream.Read(buf, 6), 6u);  // "abc" now, "de" and "f" later
    writer.join();
    EXPECT_GE(Clock::now() - t0, 250ms);
    EXPECT_EQ(std::string(buf, 6), "abcdef");
    EXPECT_EQ(stream.getPosition(), 6u);
    EXPECT_EQ(stream.bytesBehind(), 2u);
    EXPECT_EQ(stream.end(), GrowingFileEnd::None);
}

TEST(GrowingFileStream, NoGrowthForTheIdleTimeoutEndsWithAShortRead) {
    const std::string path = scratch("idle.bin");
    append(path, "xy");
    std::atomic<bool> stop{false};
    GrowingFileStream stream(path, {0.3, 0.01}, stop);
    char buf[4];
    const auto t0 = Clock::now();
    EXPECT_EQ(stream.Read(buf, 4), 2u);
    const auto waited = Clock::now() - t0;
    EXPECT_GE(waited, 250ms);
    EXPECT_LT(waited, 2s);
    EXPECT_EQ(stream.end(), GrowingFileEnd::IdleTimeout);
}

TEST(GrowingFileStream, AStopEndsAWaitingReadSoon) {
    const std::string path = scratch("stop.bin");
    std::atomic<bool> stop{false};
    GrowingFileStream stream(path, {60.0, 0.01}, stop);
    std::thread stopper([&] {
        std::this_thread::sleep_for(100ms);
        stop = true;
    });
    char buf[4];
    const auto t0 = Clock::now();
    EXPECT_EQ(stream.Read(buf, 4), 0u);
    stopper.join();
    EXPECT_LT(Clock::now() - t0, 1s);
    EXPECT_EQ(stream.end(), GrowingFileEnd::Stopped);
}

TEST(GrowingFileStream, AMissingFileIsNamed) {
    std::atomic<bool> stop{false};
    try {
        GrowingFileStream stream("/nonexistent/x.rawlog", {}, stop);
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/x.rawlog"), std::string::npos);
    }
}

TEST(GrowingTrajectory, AQueryWaitsForItsPoseWhileTheFileGrowsIncludingAPartialLine) {
    const std::string path = scratch("poses.tum");
    append(path, "10.0 0 0 0 0 0 0 1\n11.0 1 0 0 0 0 0 1\n12.0 2 0");  // third line unfinished
    std::atomic<bool> stop{false};
    GrowingTrajectory poses(path, {0.05, 5.0, 0.01, 30.0}, stop);
    EXPECT_EQ(poses.posesRead(), 2u);
    std::thread writer([&] {
        std::this_thread::sleep_for(150ms);
        append(path, " 0 0 0 0 1\n");
    });
    const auto pose = poses.poseAt(11.5);  // needs the third line: waits for it
    writer.join();
    ASSERT_TRUE(pose.has_value());
    EXPECT_NEAR(pose->translation().x(), 1.5, 1e-9);
    EXPECT_EQ(poses.posesRead(), 3u);
    EXPECT_EQ(poses.waits(), 1u);
    EXPECT_NEAR(poses.poseAt(10.5)->translation().x(), 0.5, 1e-9);  // covered: no wait
}

TEST(GrowingTrajectory, PosesThatNeverArriveEndTheWaitAfterWaitS) {
    const std::string path = scratch("stalled.tum");
    append(path, "10.0 0 0 0 0 0 0 1\n");
    std::atomic<bool> stop{false};
    GrowingTrajectory poses(path, {0.05, 0.3, 0.01, 30.0}, stop);
    const auto t0 = Clock::now();
    EXPECT_FALSE(poses.poseAt(20.0).has_value());  // beyond the tolerance of the last pose
    EXPECT_LT(Clock::now() - t0, 2s);
    EXPECT_NEAR(poses.poseAt(10.04)->translation().x(), 0.0, 1e-12);  // within tolerance
}

TEST(GrowingTrajectory, KeepsABoundedWindowOverALongRun) {
    const std::string path = scratch("long.tum");
    std::string lines;
    for (int i = 0; i < 20000; ++i) lines += std::to_string(i * 0.01) + " " + std::to_string(i) + " 0 0 0 0 0 1\n";
    append(path, lines);
    std::atomic<bool> stop{false};
    GrowingTrajectory poses(path, {0.05, 0.1, 0.01, 10.0}, stop);
    for (double t = 0.0; t < 199.0; t += 0.5) ASSERT_TRUE(poses.poseAt(t).has_value()) << t;
    EXPECT_EQ(poses.posesRead(), 20000u);
    EXPECT_LT(poses.posesKept(), 4000u);  // ~10 s of poses at 100 Hz, plus amortisation slack
    EXPECT_NEAR(poses.poseAt(199.5)->translation().x(), 19950.0, 1e-6);
}

}  // namespace
}  // namespace stairmap::io
