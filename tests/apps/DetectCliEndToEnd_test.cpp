// `stairmap detect` end to end: synthetic staircases with KNOWN geometry (1 cm Gaussian noise),
// written in every input format, must come back with the right direction, step count, rise, run,
// width, heading and location (issue 2 tolerances: rise < 1 cm, run < 1.5 cm, width < 10 cm).

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/serialization/CArchive.h>

#include <Eigen/Geometry>
#include <cmath>
#include <nlohmann/json.hpp>

#include "CliRunner.h"
#include "support/SyntheticScenes.h"
#include "io/cloud/CloudFile.h"

namespace stairmap::test {
namespace {

using nlohmann::json;

enum class FloorSource { Option, Config, Estimated };

struct EndToEndCase {
    const char* name;
    const char* extension;
    io::CloudFileEncoding encoding;
    FloorSource floor;
    StairSpec spec;
    unsigned seed;
    bool ascending() const { return spec.kind == StairKind::Ascending; }
};

void PrintTo(const EndToEndCase& c, std::ostream* os) { *os << c.name; }

constexpr double kRobotHeight = 0.6;  // [m] floor at z = -0.6 in the robot frame

StairSpec spec(bool ascending, int risers, double rise, double run, double width, double distance,
               double yaw) {
    StairSpec s;
    s.kind = ascending ? StairKind::Ascending : StairKind::Descending;
    s.num_risers = risers;
    s.rise_m = rise;
    s.run_m = run;
    s.width_m = width;
    s.distance_m = distance;
    s.yaw_rad = yaw;
    return s;
}

/// Writes the robot-frame cloud as a one-observation rawlog whose sensor sits at a tilted pose:
/// the points are stored in the sensor frame, so only a correct sensorPose brings them back.
void writeRawlogCloud(const std::string& path, const PointCloud& cloud_robot) {
    const double x = 0.1, y = -0.05, z = 0.4, yaw = 0.3, pitch = 0.1, roll = -0.05;
    const Eigen::Isometry3d T_robot_sensor =
        Eigen::Translation3d(x, y, z) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
        Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
    const Eigen::Isometry3d T_sensor_robot = T_robot_sensor.inverse();
    auto obs = mrpt::obs::CObservationPointCloud::Create();
    auto map = mrpt::maps::CSimplePointsMap::Create();
    for (const Eigen::Vector3f& p : cloud_robot) {
        const Eigen::Vector3d q = T_sensor_robot * p.cast<double>();
        map->insertPoint(float(q.x()), float(q.y()), float(q.z()));
    }
    obs->pointcloud = map;
    obs->sensorPose = mrpt::poses::CPose3D(x, y, z, yaw, pitch, roll);
    obs->sensorLabel = "lidar";
    mrpt::io::CFileGZOutputStream out;
    ASSERT_TRUE(out.open(path, 1));
    auto archive = mrpt::serialization::archiveFrom(out);
    archive << *obs;
}

double angleDiffDeg(double a, double b) {
    return std::abs(std::remainder(a - b, 360.0));
}

Eigen::Vector3d vec3(const json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }

/// An edge centre must sit on the true nosing: along the flight (run placement) within 4 cm, in
/// height within 3 cm; along the edge within `lateral_tol` (the observed extent of one edge may be
/// shorter at one end; the contract bounds only the mean width).
void expectEdgeCentreNear(const Eigen::Vector3d& got, const Eigen::Vector3d& want, const Eigen::Vector3d& heading,
                          const std::string& what, double lateral_tol) {
    const Eigen::Vector3d d = got - want;
    const Eigen::Vector3d lateral(-heading.y(), heading.x(), 0.0);
    EXPECT_LT(std::abs(d.dot(heading)), 0.04) << what << " along the flight: " << got.transpose() << " vs "
                                              << want.transpose();
    EXPECT_LT(std::abs(d.z()), 0.03) << what << " height: " << got.transpose() << " vs " << want.transpose();
    EXPECT_LT(std::abs(d.dot(lateral)), lateral_tol) << what << " along the edge: " << got.transpose() << " vs "
                                              << want.transpose();
}

class DetectCliEndToEnd : public testing::TestWithParam<EndToEndCase> {};

TEST_P(DetectCliEndToEnd, ReportsTheKnownStaircase) {
    const EndToEndCase& c = GetParam();
    const std::string dir = cliScratchDir("DetectCliEndToEnd", c.name);
    SceneOptions options;
    options.floor_z = -kRobotHeight;
    options.floor_half_size_m = 6.0;  // floor all round the flight, its landing included
    options.spacing_m = 0.007;
    options.seed = c.seed;
    SceneBuilder scene(options);
    const StairTruth truth = scene.addStairs(c.spec);
    scene.addFloor();
    const PointCloud& cloud = scene.cloud();
    const std::string path = dir + "/stairs" + c.extension;
    if (std::string(c.extension) == ".rawlog") {
        writeRawlogCloud(path, cloud);
    } else {
        io::writeCloudFile(path, cloud, c.encoding);
    }
    std::string args = "detect '" + path + "'";
    if (c.floor == FloorSource::Option) args += " --robot-height " + std::to_string(kRobotHeight);
    if (c.floor == FloorSource::Config) {
        std::ofstream(dir + "/cfg.ini") << "[detector]\nrobot_height_m = " << kRobotHeight << "\n";
        args += " --config '" + dir + "/cfg.ini'";
    }
    const CliResult r = runStairmap(args, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    ASSERT_FALSE(r.out.empty());
    EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << "stdout must be exactly one line";
    const json out = json::parse(r.out);  // throws on anything but one JSON value
    ASSERT_TRUE(out.at("time_ms").is_number());
    EXPECT_GT(out.at("time_ms").get<double>(), 0.0);
    SCOPED_TRACE(out.dump(1));
    ASSERT_EQ(out.at("staircases").size(), 1u) << "exactly the one staircase, no false positive";
    const json& s = out.at("staircases")[0];
    EXPECT_EQ(s.at("direction"), c.ascending() ? "ascending" : "descending");
    EXPECT_EQ(s.at("num_steps"), c.spec.num_risers);
    EXPECT_EQ(s.at("steps").size(), s.at("num_steps").get<std::size_t>());
    EXPECT_NEAR(s.at("step_height").get<double>(), c.spec.rise_m, 0.01);
    EXPECT_NEAR(s.at("step_depth").get<double>(), c.spec.run_m, 0.015);
    EXPECT_NEAR(s.at("step_width").get<double>(), c.spec.width_m, 0.10);
    EXPECT_NEAR(s.at("slope_deg").get<double>(), std::atan2(c.spec.rise_m, c.spec.run_m) * 180 / M_PI, 3.0);
    EXPECT_LT(angleDiffDeg(s.at("heading_deg").get<double>(), c.spec.yaw_rad * 180 / M_PI), 5.0);
    const Eigen::Vector3d heading(std::cos(c.spec.yaw_rad), std::sin(c.spec.yaw_rad), 0.0);
    expectEdgeCentreNear(vec3(s.at("location")), truth.location, heading, "location", 0.10);
    const std::size_t n = std::min(s.at("steps").size(), truth.nosings.size());
    for (std::size_t k = 0; k < n; ++k) {
        const json& step = s.at("steps")[k];
        expectEdgeCentreNear(0.5 * (vec3(step.at("start")) + vec3(step.at("end"))), 0.5 * (truth.nosings[k].first + truth.nosings[k].second), heading,
                             "step " + std::to_string(k), 0.20);
    }
    if (c.floor != FloorSource::Estimated) {
        EXPECT_EQ(out.at("floor_estimated"), false);
    }
    EXPECT_NEAR(out.at("floor_z").get<double>(), -kRobotHeight, 0.03);
}

using Enc = io::CloudFileEncoding;
INSTANTIATE_TEST_SUITE_P(
    FormatsDirectionsYaws, DetectCliEndToEnd,
    testing::Values(
        EndToEndCase{"asc_pcd_bin_front", ".pcd", Enc::Binary, FloorSource::Option,
                     spec(true, 6, 0.17, 0.29, 1.1, 2.0, 0.0), 1},
        EndToEndCase{"asc_ply_ascii_back_left", ".ply", Enc::Ascii, FloorSource::Estimated,
                     spec(true, 5, 0.15, 0.31, 1.3, 2.5, 2.4), 2},
        EndToEndCase{"asc_xyz_right", ".xyz", Enc::Ascii, FloorSource::Config,
                     spec(true, 7, 0.19, 0.27, 0.9, 1.6, -M_PI / 2), 3},
        EndToEndCase{"desc_pcd_ascii_front_left", ".pcd", Enc::Ascii, FloorSource::Option,
                     spec(false, 6, 0.18, 0.28, 1.2, 1.8, 0.5), 4},
        EndToEndCase{"desc_ply_bin_behind", ".ply", Enc::Binary, FloorSource::Option,
                     spec(false, 5, 0.16, 0.30, 1.0, 2.2, M_PI), 5},
        EndToEndCase{"desc_xyz_back_right", ".xyz", Enc::Ascii, FloorSource::Estimated,
                     spec(false, 6, 0.17, 0.32, 1.1, 2.0, -2.0), 6},
        EndToEndCase{"asc_rawlog_tilted_sensor", ".rawlog", Enc::Binary, FloorSource::Option,
                     spec(true, 6, 0.17, 0.28, 1.0, 2.2, 1.0), 7}),
    [](const testing::TestParamInfo<EndToEndCase>& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace stairmap::test
