// RobotPoseMatcher rules (nearest in time within tolerance, FIFO, forced resolution, no mixing of
// odometry once absolute poses exist) and conversion failures inside the rawlog source.
#include <gtest/gtest.h>

#include <filesystem>

#include "RawlogTestUtil.h"
#include "io/rawlog/RawlogScanSource.h"
#include "io/rawlog/RobotPoseMatcher.h"

using namespace stairmap;
using namespace stairmap::io;

namespace {

Eigen::Isometry3d atX(double x) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation().x() = x;
    return T;
}

PendingScan scanAt(double t, std::size_t index, std::optional<double> fallback_x = std::nullopt) {
    PendingScan p;
    p.scan.stamp_s = t;
    p.scan.index = index;
    if (fallback_x) p.fallback_T_world_robot = atX(*fallback_x);
    return p;
}

}  // namespace

TEST(RawlogPoseMatching, WaitsUntilStreamTimePassesTolerance) {
    RobotPoseMatcher m({0.05, 16, 256});
    m.addScan(scanAt(1.0, 0));
    m.addPose(1.03, atX(3));
    EXPECT_FALSE(m.pop(false).resolved);  // a closer pose could still come
    m.addPose(1.01, atX(1));
    m.observeStreamTime(1.2);
    const auto r = m.pop(false);
    ASSERT_TRUE(r.resolved && r.scan);
    EXPECT_DOUBLE_EQ(r.scan->T_world_robot.translation().x(), 1.0);  // nearest in time
}

TEST(RawlogPoseMatching, ExactStampResolvesAtOnceAndOrderIsKept) {
    RobotPoseMatcher m;
    m.addScan(scanAt(1.0, 0));
    m.addScan(scanAt(1.02, 1));  // e.g. a second sensor 20 ms later
    m.addPose(1.02, atX(2));     // scan 1 matches exactly, but scan 0 is still waiting
    EXPECT_FALSE(m.pop(false).resolved);
    m.addPose(1.0, atX(1));  // exact pose for scan 0: both resolve, in order
    const auto a = m.pop(false), b = m.pop(false);
    ASSERT_TRUE(a.scan && b.scan);
    EXPECT_EQ(a.scan->index, 0u);
    EXPECT_DOUBLE_EQ(a.scan->T_world_robot.translation().x(), 1.0);
    EXPECT_EQ(b.scan->index, 1u);
    EXPECT_DOUBLE_EQ(b.scan->T_world_robot.translation().x(), 2.0);
}

TEST(RawlogPoseMatching, PoseOutsideToleranceIsNotUsed) {
    RobotPoseMatcher m({0.05, 16, 256});
    m.addPose(0.9, atX(9));
    m.addScan(scanAt(1.0, 0));
    const auto r = m.pop(true);
    EXPECT_TRUE(r.resolved);
    EXPECT_FALSE(r.scan.has_value());
}

TEST(RawlogPoseMatching, FallbackOnlyWithoutAbsolutePoses) {
    RobotPoseMatcher odometry_only;
    odometry_only.addScan(scanAt(1.0, 0, 5.0));
    const auto r = odometry_only.pop(true);
    ASSERT_TRUE(r.scan);
    EXPECT_DOUBLE_EQ(r.scan->T_world_robot.translation().x(), 5.0);

    RobotPoseMatcher mixed;
    mixed.addPose(10.0, atX(1));
    mixed.addScan(scanAt(1.0, 0, 5.0));  // odometry origin differs from the world frame
    const auto r2 = mixed.pop(true);
    EXPECT_TRUE(r2.resolved);
    EXPECT_FALSE(r2.scan.has_value());
}

TEST(RawlogPoseMatching, ForcedResolutionBoundsMemory) {
    RobotPoseMatcher m({0.05, 4, 256});
    for (int i = 0; i < 5; ++i) m.addScan(scanAt(std::nan(""), i));  // no usable time at all
    const auto r = m.pop(false);  // 5 > max_pending: the oldest is resolved (without a pose)
    EXPECT_TRUE(r.resolved);
    EXPECT_FALSE(m.pop(false).resolved);
}

TEST(RawlogPoseMatching, MissingExternalCloudFileSkipsThatScanOnly) {
    const std::string dir = test::scratchDir();
    const std::string path = dir + "/external.rawlog", cloud_file = dir + "/cloud0.txt";
    {
        test::RawlogWriter w(path, false);
        auto external = test::makeCloudObs(0, mrpt::poses::CPose3D(), {{1, 0, 0}});
        external->setAsExternalStorage(cloud_file, mrpt::obs::CObservationPointCloud::ExternalStorageFormat::PlainTextFile);
        w << *test::makePoseObs(0, mrpt::poses::CPose3D());
        w << *external;
        w << *test::makePoseObs(1, mrpt::poses::CPose3D());
        w << *test::makeCloudObs(1, mrpt::poses::CPose3D(), {{2, 0, 0}});
    }
    std::filesystem::remove(cloud_file);
    RawlogScanSource src(path);
    std::size_t n = 0;
    while (auto s = src.next()) {
        EXPECT_NEAR(s->stamp_s, 1.0, 1e-6);
        ++n;
    }
    EXPECT_EQ(n, 1u);
    EXPECT_EQ(src.stats().conversion_failed, 1u);
    ASSERT_EQ(src.messages().size(), 1u);
    EXPECT_NE(src.messages()[0].find("scan index 0"), std::string::npos) << src.messages()[0];
}
