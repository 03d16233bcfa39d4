// In-memory end-to-end run of the Mapper on a simulated drive through the two-floor building
// (truth from the simulator): up stair_a, across floor 1, down stair_b, back to the start.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/Mapper.h"
#include "pipeline/SimSequence.h"

namespace stairmap::pipeline {
namespace {

const StaircaseLandmark* nearest(const LandmarkMap& map, const Eigen::Vector3d& p, double max_m) {
    const StaircaseLandmark* best = nullptr;
    double best_d = max_m;
    for (const auto& lm : map.staircases()) {
        for (const auto& e : lm.stairs.steps) {
            const double d = (e.centre() - p).head<2>().norm();
            if (d < best_d) {
                best_d = d;
                best = &lm;
            }
        }
    }
    return best;
}

TEST(TwoFloorDrive, OneLandmarkPerStaircaseWithTrueGeometry) {
    const testing::SimSequence seq = testing::makeTwoFloorSequence(2.0, sim::vlp16());
    MapperParams params;
    params.sensor.robot_height_m = testing::kBaseHeight;
    Mapper mapper(params);
    for (const Scan& scan : seq.scans) mapper.processScan(scan);

    const auto& truths = seq.scene.truth().staircases;
    ASSERT_EQ(mapper.landmarks().staircases().size(), truths.size());  // no duplicates on revisit
    for (const StaircaseTruth& truth : truths) {
        SCOPED_TRACE(truth.name);
        // The landmark whose steps lie on this flight (any nosing within 0.3 m).
        const StaircaseLandmark* lm = nullptr;
        for (const auto& n : truth.nosings) {
            if ((lm = nearest(mapper.landmarks(), n.centre(), 0.3)) != nullptr) break;
        }
        ASSERT_NE(lm, nullptr);
        EXPECT_NEAR(lm->stairs.step_height, truth.rise_m, 0.01);
        EXPECT_NEAR(lm->stairs.step_depth, truth.run_m, 0.015);
        EXPECT_NEAR(lm->stairs.step_width, truth.width_m, 0.10);
        const Eigen::Vector3d up = truth.nosings.back().centre() - truth.nosings.front().centre();
        EXPECT_NEAR(std::remainder(lm->stairs.heading_rad - std::atan2(up.y(), up.x()), 2 * M_PI),
                    0.0, 5 * M_PI / 180);
        // Its bottom floor is the ground floor, its top floor the upper one (the robot walked up
        // stair_a and down stair_b, which links each to both floors).
        bool bottom_ok = false, top_ok = false;
        for (const Floor& f : mapper.landmarks().floors()) {
            bottom_ok |= f.id == lm->bottom_floor && std::abs(f.z - truth.bottom_z) < 0.15;
            top_ok |= f.id == lm->top_floor && std::abs(f.z - truth.top_z) < 0.15;
        }
        EXPECT_TRUE(bottom_ok);
        EXPECT_TRUE(top_ok) << "top_floor " << lm->top_floor;
    }
}

}  // namespace
}  // namespace stairmap::pipeline
