// The detector on depth cameras' noisy single views from the randomised benchmark (range noise
// growing with the range squared: 4-8 cm at 3-4 m). The truth comes from the scene description.

#include <gtest/gtest.h>

#include <tuple>
#include <vector>

#include "core/StairDetector.h"
#include "support/BenchmarkScenes.h"

namespace stairmap {
namespace {

using test::benchmarkScene;
using test::reportsFlight;

/// Seed and index of a randomised-benchmark scene: a depth camera 2.9-3.7 m from a flight.
class NoisyDepthCameraFlight : public testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(NoisyDepthCameraFlight, IsFoundOnceWithItsRiseAndRun) {
    const auto [seed, index] = GetParam();
    const sim::RandomCloud scene = benchmarkScene(seed, index);
    ASSERT_EQ(scene.spec.sensor.kind, sim::RandomSensorKind::DepthCamera);
    ASSERT_FALSE(scene.truth.staircases.empty());
    const StaircaseTruth& truth = scene.truth.staircases.front();
    const DetectionResult result = StairDetector().detect(scene.cloud, scene.truth.observer_floor_z);
    std::vector<const Staircase*> found;
    for (const Staircase& s : result.staircases)
        if (reportsFlight(s, truth)) found.push_back(&s);
    ASSERT_EQ(found.size(), 1u) << result.staircases.size() << " staircases in the cloud";
    EXPECT_NEAR(found.front()->step_height, truth.rise_m, 0.01);
    // Noisy nosings read towards the camera, the farther ones by more: runs read up to 3 cm short
    // (docs/detector.md, known weaknesses).
    EXPECT_NEAR(found.front()->step_depth, truth.run_m, 0.03);
}

// Development-set scenes (tuned on). With the paper's fixed 3 cm split distance (split_noise_factor
// 0) the nosings of 249, 279 and 199 break into pieces and those flights are missed.
INSTANTIATE_TEST_SUITE_P(DevScenes, NoisyDepthCameraFlight,
                         testing::Values(std::make_tuple(1001, 155), std::make_tuple(1001, 249),
                                         std::make_tuple(1001, 279), std::make_tuple(1001, 288),
                                         std::make_tuple(3003, 31), std::make_tuple(3003, 224)));

/// A far VLP-16 sees a wide flight's nosings in pieces: two chains through them, side by side, are
/// one flight once their treads are measured (dev2 scene 70, reported twice before).
TEST(FlightSeenInPieces, IsReportedOnce) {
    const sim::RandomCloud scene = benchmarkScene(3003, 70);
    ASSERT_FALSE(scene.truth.staircases.empty());
    const StaircaseTruth& truth = scene.truth.staircases.front();
    const DetectionResult result = StairDetector().detect(scene.cloud, scene.truth.observer_floor_z);
    int on_truth = 0;
    for (const Staircase& s : result.staircases) on_truth += reportsFlight(s, truth) ? 1 : 0;
    EXPECT_EQ(on_truth, 1) << result.staircases.size() << " staircases in the cloud";
}

}  // namespace
}  // namespace stairmap
