// The detector on real data kept outside the project: the ANYmal elevation map of a building
// entrance in shared/data/real/anymal_heightmap (8-bit heights, 0-1.25 m over 0-255, cell size not
// stored: about 3-4 cm). Its stairs, read off the image independently of the detector: the floor
// at grey 39, a 0.09 m step, a 0.10 m step onto a landing (grey ~78, about 30 cells deep), then
// three rises of 0.186-0.19 m (grey 116, 155, 193) with treads 13-15 cells deep, the top tread
// mapped for 10-12 cells, then unknown. Robots on the floor in front (image column 118), on the
// lower step (column 95) and on the landing (column 65, about the map's centre, where a
// robot-centric elevation map puts its robot), all facing the stairs, must find the three rises
// as one ascending flight whatever the cell size, with the floor given or estimated.
#include <gtest/gtest.h>

#include <mrpt/img/CImage.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/StairDetector.h"

namespace stairmap {
namespace {

constexpr double kGreyToMetres = 1.25 / 255.0;
constexpr double kRobotHeight = 0.5;  // [m] robot frame origin above the cell it stands on
constexpr int kRobotRow = 35;         // the middle of the flight's width
constexpr double kTrueRise = (193.0 - 78.0) / 3.0 * kGreyToMetres;  // 0.188 m

/// The height map as a cloud in the frame of a robot standing on (column, kRobotRow), x towards
/// decreasing columns (the stairs), one point per cell, unknown cells (grey 0) left out.
PointCloud entranceCloud(double cell_m, int column) {
    mrpt::img::CImage image;
    const std::string path =
        std::string(STAIRMAP_SHARED_DIR) + "/data/real/anymal_heightmap/real_stairs_125cm.png";
    if (!image.loadFromFile(path, 0)) throw std::runtime_error("cannot read " + path);
    const double floor = image.at<uint8_t>(column, kRobotRow) * kGreyToMetres;
    PointCloud cloud;
    const int rows = static_cast<int>(image.getHeight()), columns = static_cast<int>(image.getWidth());
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const uint8_t grey = image.at<uint8_t>(c, r);
            if (grey == 0) continue;
            cloud.emplace_back(float((column - c) * cell_m), float((kRobotRow - r) * cell_m),
                               float(grey * kGreyToMetres - floor - kRobotHeight));
        }
    }
    return cloud;
}

/// Cell size [m], the robot's image column, whether the floor height is given.
class AnymalEntrance : public testing::TestWithParam<std::tuple<double, int, bool>> {};

TEST_P(AnymalEntrance, ItsThreeRisesAboveTheLandingAreOneFlight) {
    const auto [cell, column, floor_given] = GetParam();
    const PointCloud cloud = entranceCloud(cell, column);
    ASSERT_GT(cloud.size(), 5000u);
    const std::optional<double> floor =
        floor_given ? std::optional<double>(-kRobotHeight) : std::nullopt;
    const DetectionResult r = StairDetector().detect(cloud, floor);
    ASSERT_EQ(r.staircases.size(), 1u);
    const Staircase& s = r.staircases.front();
    EXPECT_EQ(s.direction, StairDirection::Ascending);
    EXPECT_EQ(s.steps.size(), 3u);
    EXPECT_NEAR(s.step_height, kTrueRise, 0.02);
    // The treads are 13-15 cells deep (the slanted map reads them unevenly).
    EXPECT_GT(s.step_depth, 12.5 * cell);
    EXPECT_LT(s.step_depth, 16.5 * cell);
    // The first nosing is the landing's far end: image columns 50-52.
    EXPECT_NEAR(s.steps.front().centre().x(), (column - 51) * cell, 3 * cell);
}

// 3 cm, 3.3 cm (the 1.1 m landing of the description) and 4 cm (the data's README) cells.
INSTANTIATE_TEST_SUITE_P(
    Standpoints, AnymalEntrance,
    testing::Combine(testing::Values(0.03, 0.033, 0.04), testing::Values(118, 95, 65),
                     testing::Bool()));

}  // namespace
}  // namespace stairmap
