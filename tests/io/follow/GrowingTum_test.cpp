// A TUM file still being written: complete lines are read as they appear, a half-written last
// line waits, errors name the file and line, and old poses are forgotten in bounded memory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "io/follow/GrowingTum.h"

namespace stairmap::io {
namespace {

std::string scratch(const std::string& name, const std::string& text) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "growing_tum";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::trunc | std::ios::binary) << text;
    return path;
}

void append(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::app | std::ios::binary) << text << std::flush;
}

std::string tumLine(double t, double x) {
    std::ostringstream s;
    s << std::setprecision(17) << t << " " << x << " 0 0 0 0 0 1\n";
    return s.str();
}

TEST(GrowingTum, ReadsCompletedLinesAndWaitsForAPartialOne) {
    const std::string path = scratch("partial.tum", "# t x y z qx qy qz qw\n");
    GrowingTum tum(path);
    EXPECT_FALSE(tum.refresh());
    append(path, tumLine(10.0, 1.0) + "11.0 2 0 0 0 0");  // the second line is still being written
    EXPECT_TRUE(tum.refresh());
    EXPECT_EQ(tum.trajectory().size(), 1u);
    append(path, " 0 1\n");
    EXPECT_TRUE(tum.refresh());
    ASSERT_EQ(tum.trajectory().size(), 2u);
    EXPECT_NEAR(tum.trajectory().poseAt(10.5)->translation().x(), 1.5, 1e-12);
    EXPECT_EQ(tum.posesRead(), 2u);
}

TEST(GrowingTum, ErrorsNameTheFileAndLine) {
    EXPECT_THROW(GrowingTum(scratch("x", "") + ".missing"), std::runtime_error);
    const std::string path = scratch("backwards.tum", tumLine(2.0, 0) + tumLine(1.0, 0));
    GrowingTum tum(path);
    try {
        tum.refresh();
        FAIL() << "no error for a time going back";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path + ":2:"), std::string::npos) << e.what();
    }
    const std::string shrinking = scratch("shrinking.tum", tumLine(1.0, 0) + tumLine(2.0, 0));
    GrowingTum tum2(shrinking);
    tum2.refresh();
    scratch("shrinking.tum", tumLine(1.0, 0));
    EXPECT_THROW(tum2.refresh(), std::runtime_error);
}

TEST(GrowingTum, ForgetsOldPosesButKeepsOneForInterpolation) {
    std::string text;
    for (int i = 0; i < 100; ++i) text += tumLine(double(i), double(i));
    const std::string path = scratch("forget.tum", text);
    GrowingTum tum(path);
    tum.refresh();
    tum.forgetBefore(20.5);  // fewer than half could go: nothing is copied yet
    EXPECT_EQ(tum.trajectory().size(), 100u);
    tum.forgetBefore(80.5);
    ASSERT_EQ(tum.trajectory().size(), 20u);  // poses 80 .. 99
    EXPECT_NEAR(tum.trajectory().poseAt(80.5)->translation().x(), 80.5, 1e-12);
    EXPECT_FALSE(tum.trajectory().poseAt(79.0).has_value());
    append(path, tumLine(100.0, 100.0));  // reading goes on where it was
    EXPECT_TRUE(tum.refresh());
    EXPECT_EQ(tum.trajectory().size(), 21u);
    EXPECT_EQ(tum.posesRead(), 101u);
}

}  // namespace
}  // namespace stairmap::io
