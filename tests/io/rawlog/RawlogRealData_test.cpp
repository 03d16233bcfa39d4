// Real rawlogs (no poses inside) through RawlogScanSource: read without crash, scans counted and
// skipped for lack of pose, and emitted with all their points once a TUM trajectory is given.
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include "VelodyneTestUtil.h"
#include "io/rawlog/RawlogScanSource.h"

using namespace stairmap;
using namespace stairmap::io;

namespace {

const std::string kRealDir = std::string(STAIRMAP_SHARED_DIR) + "/data/real/";

struct Case {
    const char* file;
    std::size_t scans;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.file; }  // readable test names

// Points a scan must yield, counted straight from the raw data: Velodyne returns with range in
// [max(1 m, minRange), maxRange]; depth pixels with a non-zero range.
std::size_t expectedPoints(const mrpt::obs::CObservation& o) {
    std::size_t n = 0;
    if (const auto* v = dynamic_cast<const mrpt::obs::CObservationVelodyneScan*>(&o)) {
        for (const auto& pkt : v->scan_packets) {
            n += test::countValidReturns(reinterpret_cast<const std::uint8_t*>(&pkt),
                                         std::max(1.0, v->minRange), v->maxRange);
        }
    } else if (const auto* r = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&o)) {
        for (int row = 0; row < r->rangeImage.rows(); ++row) {
            for (int col = 0; col < r->rangeImage.cols(); ++col) n += r->rangeImage(row, col) > 0;
        }
    }
    return n;
}

// Timestamps and expected point counts of all observations, read independently of the source.
std::vector<double> observationStamps(const std::string& path, std::vector<std::size_t>* points = nullptr) {
    mrpt::io::CFileGZInputStream f(path);
    auto ar = mrpt::serialization::archiveFrom(f);
    std::vector<double> stamps;
    auto add = [&](const mrpt::obs::CObservation& o) {
        stamps.push_back(mrpt::Clock::toDouble(o.timestamp));
        if (points) points->push_back(expectedPoints(o));
    };
    try {
        for (;;) {
            auto obj = ar.ReadObject();
            if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) add(*o);
            if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
                for (const auto& o : *sf) add(*o);
            }
        }
    } catch (const std::exception&) {
    }
    return stamps;
}

}  // namespace

class RawlogRealData : public ::testing::TestWithParam<Case> {};

TEST_P(RawlogRealData, NoPoseMeansSkippedAndCounted) {
    const Case& c = GetParam();
    RawlogScanSource src(kRealDir + c.file);
    EXPECT_FALSE(src.next().has_value());
    EXPECT_EQ(src.stats().scans_read, c.scans);
    EXPECT_EQ(src.stats().skipped_no_pose, c.scans);
    EXPECT_EQ(src.stats().scans_emitted, 0u);
    EXPECT_EQ(src.messages().size(), 1u);
}

TEST_P(RawlogRealData, WithTrajectoryAllScansEmitted) {
    const Case& c = GetParam();
    const std::string path = kRealDir + c.file;
    std::vector<std::size_t> points;
    const auto stamps = observationStamps(path, &points);
    ASSERT_EQ(points.size(), c.scans);
    ASSERT_FALSE(stamps.empty());
    TumTrajectory traj;  // robot standing at (2, 0, 0) over the whole log
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(2, 0, 0);
    traj.append(*std::min_element(stamps.begin(), stamps.end()) - 1.0, T);
    traj.append(*std::max_element(stamps.begin(), stamps.end()) + 1.0, T);
    RawlogScanSource src(path, {}, traj);
    std::vector<Scan> scans;
    while (auto s = src.next()) scans.push_back(std::move(*s));
    ASSERT_EQ(scans.size(), c.scans);
    for (std::size_t k = 0; k < scans.size(); ++k) {
        EXPECT_EQ(scans[k].points_robot.size(), points[k]) << c.file << " scan " << k;
        EXPECT_TRUE(scans[k].T_world_robot.translation().isApprox(Eigen::Vector3d(2, 0, 0)));
        EXPECT_EQ(scans[k].index, k);
    }
    EXPECT_EQ(src.stats().skipped_no_pose, 0u);
    EXPECT_TRUE(src.stats().unsupported.empty());
}

INSTANTIATE_TEST_SUITE_P(
    Files, RawlogRealData,
    ::testing::Values(Case{"sample_velodyne_vlp16_gps.rawlog", 3},
                      Case{"sample_velodyne_hdl32.rawlog", 2}, Case{"test_velodyne_VLP16.rawlog", 1},
                      Case{"test-3d-obs-ground.rawlog", 1}),
    [](const auto& param_info) {
        std::string n = param_info.param.file;
        n = n.substr(0, n.find('.'));
        for (char& ch : n) {
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        }
        return n;
    });
