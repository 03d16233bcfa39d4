#include "map/FloorLevels.h"

#include <algorithm>
#include <cmath>

#include "map/StaircaseTraversal.h"

namespace stairmap {
namespace {

constexpr double kDefaultRise = 0.15;  // [m] for a single-step flight without a rise estimate

void updateHeight(Floor& f) {
    if (f.robot_samples > 0) {
        f.z = f.robot_z_sum / f.robot_samples;
    } else if (f.staircase_ends > 0) {
        f.z = f.end_z_sum / f.staircase_ends;
    }
}

/// Index of the level nearest to z within tol (optionally only reported ones), -1 if none.
int nearestLevel(const LandmarkMapState& state, double z, const LandmarkParams& params,
                 bool reported_only) {
    int best = -1;
    double best_dist = params.floor_merge_tolerance_m;
    for (std::size_t i = 0; i < state.floor_levels.size(); ++i) {
        const Floor& f = state.floor_levels[i];
        if (reported_only && !isReportedFloor(f, params)) continue;
        const double dist = std::abs(f.z - z);
        if (dist <= best_dist) {
            best = static_cast<int>(i);
            best_dist = dist;
        }
    }
    return best;
}

void mergeCloseLevels(LandmarkMapState& state, const LandmarkParams& params) {
    auto& levels = state.floor_levels;
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t i = 0; i < levels.size() && !merged; ++i) {
            for (std::size_t j = i + 1; j < levels.size() && !merged; ++j) {
                if (std::abs(levels[i].z - levels[j].z) > params.floor_merge_tolerance_m) continue;
                Floor& keep = levels[i].id < levels[j].id ? levels[i] : levels[j];
                const Floor& gone = levels[i].id < levels[j].id ? levels[j] : levels[i];
                keep.robot_samples += gone.robot_samples;
                keep.robot_z_sum += gone.robot_z_sum;
                keep.staircase_ends += gone.staircase_ends;
                keep.end_z_sum += gone.end_z_sum;
                updateHeight(keep);
                levels.erase(levels.begin() + static_cast<long>(&gone == &levels[i] ? i : j));
                merged = true;
            }
        }
    }
}

void addStaircaseEnd(LandmarkMapState& state, double z, const LandmarkParams& params) {
    int idx = nearestLevel(state, z, params, false);
    if (idx < 0) {
        Floor f;
        f.id = state.next_floor_id++;
        f.z = z;
        state.floor_levels.push_back(f);
        idx = static_cast<int>(state.floor_levels.size()) - 1;
    }
    state.floor_levels[idx].staircase_ends += 1;
    state.floor_levels[idx].end_z_sum += z;
}

int reportedFloorId(const LandmarkMapState& state, double z, const LandmarkParams& params) {
    const int idx = nearestLevel(state, z, params, true);
    return idx < 0 ? -1 : state.floor_levels[idx].id;
}

/// The latest climb through the flight names its floors; otherwise its seen ends do.
void linkFloors(const LandmarkMapState& state, StaircaseLandmark& lm, const LandmarkParams& params) {
    if (lm.stairs.steps.empty()) return;
    lm.bottom_floor = reportedFloorId(state, staircaseBottomZ(lm.stairs), params);
    lm.top_floor = reportedFloorId(state, staircaseTopZ(lm.stairs), params);
    for (auto t = state.transits.rbegin(); t != state.transits.rend(); ++t) {
        const std::optional<TraversedFloors> floors = traversedFloors(lm.stairs, *t, params);
        if (!floors) continue;
        const int low = reportedFloorId(state, floors->low_z, params);
        const int high = reportedFloorId(state, floors->high_z, params);
        if (low >= 0) lm.bottom_floor = low;
        if (high >= 0) lm.top_floor = high;
        return;
    }
}

}  // namespace

double staircaseBottomZ(const Staircase& s) {
    const double rise = s.step_height > 0.0 ? s.step_height : kDefaultRise;
    return s.steps.front().centre().z() - rise;
}

double staircaseTopZ(const Staircase& s) { return s.steps.back().centre().z(); }

bool isReportedFloor(const Floor& floor, const LandmarkParams& params) {
    return floor.robot_samples >= params.floor_min_robot_samples || floor.staircase_ends > 0;
}

void addRobotFloorSample(LandmarkMapState& state, double z, const LandmarkParams& params) {
    const int idx = nearestLevel(state, z, params, false);
    if (idx < 0) {
        Floor f;
        f.id = state.next_floor_id++;
        f.robot_samples = 1;
        f.robot_z_sum = z;
        f.z = z;
        state.floor_levels.push_back(f);
    } else {
        Floor& f = state.floor_levels[idx];
        f.robot_samples += 1;
        f.robot_z_sum += z;
        updateHeight(f);
    }
    mergeCloseLevels(state, params);
}

void refreshFloorLevels(LandmarkMapState& state, const LandmarkParams& params) {
    // Ends are recomputed from scratch; each level keeps its last height as the anchor meanwhile.
    for (Floor& f : state.floor_levels) {
        f.staircase_ends = 0;
        f.end_z_sum = 0.0;
    }
    for (const StaircaseLandmark& lm : state.staircases) {
        if (!lm.confirmed || lm.stairs.steps.empty()) continue;
        if (lm.bottom_observed) addStaircaseEnd(state, staircaseBottomZ(lm.stairs), params);
        if (lm.top_observed) addStaircaseEnd(state, staircaseTopZ(lm.stairs), params);
    }
    auto& levels = state.floor_levels;
    levels.erase(std::remove_if(levels.begin(), levels.end(),
                                [](const Floor& f) { return f.support() == 0; }),
                 levels.end());
    for (Floor& f : levels) updateHeight(f);
    mergeCloseLevels(state, params);
    std::sort(levels.begin(), levels.end(),
              [](const Floor& a, const Floor& b) { return a.id < b.id; });
    for (StaircaseLandmark& lm : state.staircases) linkFloors(state, lm, params);
}

}  // namespace stairmap
