#pragma once
// Expectations on the randomised benchmark's scenes shared by the scene suites (gtest side):
// whether a detector configuration finds a scene's flight.

#include <gtest/gtest.h>

#include <initializer_list>
#include <optional>
#include <ostream>
#include <utility>
#include <vector>

#include "core/Evaluation.h"
#include "core/StairDetector.h"
#include "support/BenchmarkScenes.h"

namespace stairmap::test {

/// How many of the flights detected with `params` report the scene's first truth flight.
inline int flightsOnTruth(const sim::RandomCloud& scene, const DetectorParams& params) {
    int n = 0;
    for (const Staircase& s :
         StairDetector(params).detect(scene.cloud, scene.truth.observer_floor_z).staircases)
        n += reportsFlight(s, scene.truth.staircases.front());
    return n;
}

/// No flight is found on the truth of any benchmark scene (seed, index) of `scenes` with `off`
/// (the detector with the pass under test turned off): that pass is what finds them.
inline void expectNoneFoundWith(std::initializer_list<std::pair<int, int>> scenes,
                                const DetectorParams& off) {
    for (const auto& [seed, index] : scenes) {
        const sim::RandomCloud scene = benchmarkScene(seed, index);
        ASSERT_FALSE(scene.truth.staircases.empty());
        EXPECT_EQ(flightsOnTruth(scene, off), 0) << "seed " << seed << " scene " << index;
    }
}

/// The flights the detector (default parameters, floor at floor_z) reports on `truth`, each
/// checked to lie on its nosings as `make eval` counts them (median edge distances) and to read
/// its rise within 1 cm and its run within 3 cm.
inline std::vector<Staircase> flightsReadOnTruth(const sim::RandomCloud& scene,
                                                 const StaircaseTruth& truth, double floor_z) {
    std::vector<Staircase> on_truth;
    for (const Staircase& s : StairDetector().detect(scene.cloud, floor_z).staircases) {
        if (!reportsFlight(s, truth)) continue;
        const EdgeDistances d = edgeDistances(s, truth);
        EXPECT_LT(d.median_xy_m, EvaluationParams().max_xy_m);
        EXPECT_LT(d.median_z_m, EvaluationParams().max_z_m);
        EXPECT_NEAR(s.step_height, truth.rise_m, 0.01);
        EXPECT_NEAR(s.step_depth, truth.run_m, 0.03);
        on_truth.push_back(s);
    }
    return on_truth;
}

/// A benchmark scene of a parameterised suite: which one and why it is there.
struct NamedScene {
    int seed = 0, index = 0;
    const char* why = "";
};

inline std::ostream& operator<<(std::ostream& os, const NamedScene& c) {
    return os << "seed " << c.seed << " scene " << c.index << " (" << c.why << ")";
}

/// The flight read on the only truth flight of a single-flight scene (flightsReadOnTruth, floor
/// from the truth), with that truth: nullopt, with a test failure, when the scene is not one or
/// the flight is read other than once.
inline std::optional<std::pair<Staircase, StaircaseTruth>> onlyFlightReadOnTruth(
    const NamedScene& c) {
    const sim::RandomCloud scene = benchmarkScene(c.seed, c.index);
    const bool single = scene.truth.staircases.size() == 1 && scene.truth.observer_floor_z;
    EXPECT_TRUE(single) << c;
    if (!single) return std::nullopt;
    const StaircaseTruth& truth = scene.truth.staircases.front();
    const auto on_truth = flightsReadOnTruth(scene, truth, *scene.truth.observer_floor_z);
    EXPECT_EQ(on_truth.size(), 1u) << c;
    if (on_truth.size() != 1) return std::nullopt;
    return std::make_pair(on_truth.front(), truth);
}

}  // namespace stairmap::test
