// `stairmap detect` on the bundled spiral clouds reads each spiral as wide as its truth: the walk
// across a nosing seen in dashes (StepExtentParams::max_open_gap_m) is for straight flights only,
// a spiral's radial nosing line runs on across its column and past its rim. Truth from the
// clouds' gt.json.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "CliRunner.h"

namespace stairmap::test {
namespace {

using nlohmann::json;

const std::string kClouds = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/clouds/";

class BundledSpiralWidth : public testing::TestWithParam<const char*> {};

TEST_P(BundledSpiralWidth, IsReadWithinFiveCentimetres) {
    const std::string name = GetParam();
    std::ifstream in(kClouds + name + ".gt.json");
    const json truth = json::parse(in);
    ASSERT_EQ(truth.at("staircases").size(), 1u);
    const double width = truth.at("staircases").at(0).at("width_m").get<double>();
    const double robot_height = -truth.at("observer_floor_z").get<double>();
    const CliResult r = runStairmap(
        "detect '" + kClouds + name + ".pcd.gz' --robot-height " + std::to_string(robot_height),
        cliScratchDir("BundledSpiralWidth", name));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json found = json::parse(r.out).at("staircases");
    ASSERT_EQ(found.size(), 1u) << r.out;
    // Before the walk was limited to straight flights: 1.50 m and 1.42 m for 1.28 m.
    EXPECT_NEAR(found.at(0).at("step_width").get<double>(), width, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Clouds, BundledSpiralWidth, testing::Values("spiral_0", "spiral_4"));

}  // namespace
}  // namespace stairmap::test
