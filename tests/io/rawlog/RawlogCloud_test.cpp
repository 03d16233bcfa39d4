// Reading one cloud from an MRPT rawlog: robot frame via sensorPose, both rawlog formats, gz,
// first-3D-observation rule, and bad rawlogs.

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "io/cloud/CloudFileTestUtil.h"
#include "io/cloud/CloudFile.h"

namespace stairmap::io {
namespace {

using mrpt::obs::CObservationPointCloud;

const PointCloud kSensorPoints = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {4, -1, 0.5f}};

// Sensor extrinsics as yaw/pitch/roll (MRPT's CPose3D convention R = Rz(yaw) Ry(pitch) Rx(roll)).
constexpr double kX = 0.2, kY = -0.1, kZ = 0.5, kYaw = M_PI / 2, kPitch = -0.35, kRoll = 0.15;

/// The expected robot-frame points, computed here with Eigen (independent of the library).
PointCloud expectedRobotPoints() {
    const Eigen::Isometry3d T_robot_sensor =
        Eigen::Translation3d(kX, kY, kZ) * Eigen::AngleAxisd(kYaw, Eigen::Vector3d::UnitZ()) *
        Eigen::AngleAxisd(kPitch, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(kRoll, Eigen::Vector3d::UnitX());
    PointCloud out;
    for (const auto& p : kSensorPoints) out.push_back((T_robot_sensor * p.cast<double>()).cast<float>());
    return out;
}

CObservationPointCloud::Ptr makeObservation(const PointCloud& points) {
    auto obs = CObservationPointCloud::Create();
    auto map = mrpt::maps::CSimplePointsMap::Create();
    for (const auto& p : points) map->insertPoint(p.x(), p.y(), p.z());
    obs->pointcloud = map;
    obs->sensorPose = mrpt::poses::CPose3D(kX, kY, kZ, kYaw, kPitch, kRoll);
    obs->sensorLabel = "lidar";
    return obs;
}

/// Writes objects to a rawlog (gzip level 0 = plain stream through the gz writer, else gzipped).
void writeRawlog(const std::string& path, const std::vector<mrpt::serialization::CSerializable::Ptr>& objects,
                 int gz_level = 1) {
    mrpt::io::CFileGZOutputStream out;
    ASSERT_TRUE(out.open(path, gz_level));
    auto archive = mrpt::serialization::archiveFrom(out);
    for (const auto& o : objects) archive << *o;
}

void expectNear(const PointCloud& got, const PointCloud& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_LT((got[i] - want[i]).norm(), 1e-5f) << "point " << i << ": " << got[i].transpose() << " vs "
                                                    << want[i].transpose();
    }
}

TEST(RawlogCloud, ObservationsFormatGivesRobotFramePoints) {
    const std::string path = test::scratchDir("RawlogCloud", "format2") + "/one.rawlog";
    auto odometry = mrpt::obs::CObservationOdometry::Create();  // not 3D: skipped
    writeRawlog(path, {odometry, makeObservation(kSensorPoints)});
    const PointCloud cloud = readCloudFile(path);
    expectNear(cloud, expectedRobotPoints());
    // Sanity of the independent expectation: sensor x axis (yawed +90 deg) points along robot +y.
    EXPECT_GT(cloud[0].y(), 0.5f);
}

TEST(RawlogCloud, SensoryFrameFormatAndPlainFileWork) {
    const std::string path = test::scratchDir("RawlogCloud", "format1") + "/frames.rawlog";
    auto actions = mrpt::obs::CActionCollection::Create();
    auto frame = mrpt::obs::CSensoryFrame::Create();
    frame->insert(mrpt::obs::CObservationOdometry::Create());
    frame->insert(makeObservation(kSensorPoints));
    writeRawlog(path, {actions, frame}, 0);
    expectNear(readCloudFile(path), expectedRobotPoints());
}

TEST(RawlogCloud, FirstThreeDObservationIsUsed) {
    const std::string path = test::scratchDir("RawlogCloud", "first") + "/two.rawlog";
    writeRawlog(path, {makeObservation(kSensorPoints), makeObservation({{9, 9, 9}})});
    expectNear(readCloudFile(path), expectedRobotPoints());
}

TEST(RawlogCloud, NonFinitePointsDroppedAndAllNonFiniteIsAnError) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::string dir = test::scratchDir("RawlogCloud", "nonfinite");
    writeRawlog(dir + "/mixed.rawlog", {makeObservation({{nan, 0, 0}, {1, 0, 0}})});
    EXPECT_EQ(readCloudFile(dir + "/mixed.rawlog").size(), 1u);
    writeRawlog(dir + "/nan.rawlog", {makeObservation({{nan, 0, 0}, {0, nan, 0}})});
    test::expectReadError([&] { readCloudFile(dir + "/nan.rawlog"); }, dir + "/nan.rawlog: ",
                          "contains no finite points");
}

TEST(RawlogCloud, NoThreeDObservationIsAnError) {
    const std::string path = test::scratchDir("RawlogCloud", "none") + "/odo.rawlog";
    writeRawlog(path, {mrpt::obs::CObservationOdometry::Create(), mrpt::obs::CObservationOdometry::Create()});
    test::expectReadError([&] { readCloudFile(path); }, path + ": ", "no 3D observation");
}

TEST(RawlogCloud, TruncatedRawlogIsAnError) {
    const std::string dir = test::scratchDir("RawlogCloud", "truncated");
    PointCloud many;
    for (int i = 0; i < 1000; ++i) many.emplace_back(float(i), 1.0f, 2.0f);
    writeRawlog(dir + "/full.rawlog", {makeObservation(many)}, 0);
    std::ifstream in(dir + "/full.rawlog", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 12000u);
    for (std::size_t cut : {std::size_t{3}, std::size_t{40}, bytes.size() / 2, bytes.size() * 3 / 4}) {
        const std::string path = dir + "/cut" + std::to_string(cut) + ".rawlog";
        test::writeRaw(path, bytes.substr(0, cut));
        SCOPED_TRACE(path);
        const std::string what = test::expectReadError([&] { readCloudFile(path); }, path + ": ", "truncated");
        EXPECT_EQ(what.find('\n'), std::string::npos) << "one line, no MRPT call trace: " << what;
    }
}

}  // namespace
}  // namespace stairmap::io

namespace stairmap::io {
namespace {

TEST(RawlogCloud, MutatedBytesGiveErrorsOrPointsNeverACrash) {
    const std::string dir = test::scratchDir("RawlogCloud", "mutated");
    writeRawlog(dir + "/valid.rawlog", {makeObservation(kSensorPoints)}, 0);
    std::ifstream in(dir + "/valid.rawlog", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::mt19937 rng(5);
    for (int trial = 0; trial < 200; ++trial) {
        std::string mutated = bytes;
        for (int k = 0; k < 2; ++k) mutated[rng() % mutated.size()] = static_cast<char>(rng() & 0xff);
        const std::string path = dir + "/m.rawlog";
        test::writeRaw(path, mutated);
        try {
            readCloudFile(path);
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        }
    }
}

}  // namespace
}  // namespace stairmap::io
