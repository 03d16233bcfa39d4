#pragma once
// Expectations on the randomised benchmark's scenes shared by the scene suites (gtest side):
// whether a detector configuration finds a scene's flight.

#include <gtest/gtest.h>

#include <initializer_list>
#include <utility>

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

}  // namespace stairmap::test
