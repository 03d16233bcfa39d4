// The detector on depth cameras' noisy single views from the randomised benchmark (range noise
// growing with the range squared: 4-8 cm at 3-4 m). The truth comes from the scene description.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "core/StairDetector.h"
#include "sim/CloudSampler.h"
#include "sim/RandomCloud.h"

namespace stairmap {
namespace {

/// XY distance from p to the segment a-b.
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

/// XY distance from p to the nearest true nosing of `truth` whose height is within dz of z.
double distanceToNosings(const Eigen::Vector3d& p, const StaircaseTruth& truth, double dz) {
    double best = 1e9;
    for (const NosingSegment& n : truth.nosings) {
        if (std::abs(p.z() - n.start.z()) < dz)
            best = std::min(best, distanceToSegment(p.head<2>(), n.start.head<2>(), n.end.head<2>()));
    }
    return best;
}

/// Is `s` a report of the flight `truth`: half of its edges or more within 0.3 m of a true nosing
/// of about their height (a second chain through the same flight's scattered nosings counts too)?
bool reportsFlight(const Staircase& s, const StaircaseTruth& truth) {
    std::size_t near = 0;
    for (const StairEdge& e : s.steps) near += distanceToNosings(e.centre(), truth, 0.08) < 0.3 ? 1 : 0;
    return 2 * near >= s.steps.size();
}

/// Scene `index` of the randomised set `seed` as `stairmap sim --random` writes it (coordinates in
/// 2^-9 m steps, points sorted), so the cloud is the one `make eval` scores.
sim::RandomCloud benchmarkScene(int seed, int index) {
    sim::RandomCloud scene = sim::makeRandomCloud(static_cast<std::uint64_t>(seed), index);
    sim::quantizeAndSort(scene.cloud, 1.0 / 512.0, true);
    return scene;
}

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
