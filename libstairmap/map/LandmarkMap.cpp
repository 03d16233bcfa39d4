#include "map/LandmarkMap.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "core/StaircaseCanonical.h"
#include "core/StaircaseMerge.h"
#include "map/FloorLevels.h"
#include "map/StaircaseAssociation.h"

namespace stairmap {
namespace {

/// Seen often enough, and grown to a real flight (partial detections of 3 nosings are accepted).
bool isConfirmed(const StaircaseLandmark& lm, const LandmarkParams& p) {
    return lm.observations >= p.confirm_observations &&
           static_cast<int>(lm.stairs.steps.size()) >= p.confirm_min_steps;
}

void fail(const std::string& what) { throw std::invalid_argument("LandmarkMapState: " + what); }

void validateLandmark(const StaircaseLandmark& lm, const LandmarkMapState& state) {
    const std::string name = "staircase " + std::to_string(lm.id);
    if (lm.id < 0 || lm.id >= state.next_landmark_id) fail(name + ": id not below next_landmark_id");
    if (lm.stairs.steps.empty()) fail(name + ": has no steps");
    if (lm.step_observations.size() != lm.stairs.steps.size())
        fail(name + ": step_observations does not match the number of steps");
    for (const StairEdge& e : lm.stairs.steps) {
        if (!e.start.allFinite() || !e.end.allFinite() || !e.cov_rho_theta.allFinite())
            fail(name + ": non-finite step");
    }
    if (lm.observations < 1) fail(name + ": observations < 1");
}

void validateState(const LandmarkMapState& state) {
    std::set<int> ids;
    for (const StaircaseLandmark& lm : state.staircases) {
        validateLandmark(lm, state);
        if (!ids.insert(lm.id).second) fail("duplicate staircase id " + std::to_string(lm.id));
    }
    for (const auto& [gone, into] : state.absorbed) {
        if (ids.count(gone) || gone < 0 || gone >= state.next_landmark_id)
            fail("absorbed id " + std::to_string(gone) + " is invalid");
        (void)into;
    }
    std::set<int> floor_ids;
    for (const Floor& f : state.floor_levels) {
        if (f.id < 0 || f.id >= state.next_floor_id || !floor_ids.insert(f.id).second)
            fail("floor id " + std::to_string(f.id) + " is duplicate or not below next_floor_id");
        if (!std::isfinite(f.z)) fail("floor " + std::to_string(f.id) + ": non-finite z");
    }
    for (std::size_t i = 0; i < state.transits.size(); ++i) {
        const std::vector<Eigen::Vector3d>& path = state.transits[i].floor_path;
        const bool finite = std::all_of(path.begin(), path.end(),
                                        [](const Eigen::Vector3d& p) { return p.allFinite(); });
        if (path.size() < 3 || !finite)
            fail("transit " + std::to_string(i) + ": fewer than 3 samples or non-finite ones");
    }
}

WeightedStaircase weighted(const StaircaseLandmark& lm) {
    return {lm.stairs, lm.step_observations};
}

/// Algorithm 2 (core/StaircaseMerge.h) on two flights sameStaircase() already associated (by a
/// Definition-2 step pair, footprint overlap or continuation), so no common step is required.
void mergeInto(StaircaseLandmark& lm, const WeightedStaircase& other, const LandmarkParams& params) {
    std::optional<WeightedStaircase> merged =
        mergeCanonical(weighted(lm), other, toMergeParams(params), StepAnchor::AssociatedElsewhere);
    lm.stairs = std::move(merged->stairs);
    lm.step_observations = std::move(merged->step_observations);
}

}  // namespace

LandmarkMap::LandmarkMap(const LandmarkParams& params) : params_(params) {
    validateLandmarkParams(params_);
}

LandmarkMap::LandmarkMap(LandmarkMapState state, const LandmarkParams& params)
    : params_(params), state_(std::move(state)) {
    validateLandmarkParams(params_);
    validateState(state_);
    std::sort(state_.staircases.begin(), state_.staircases.end(),
              [](const auto& a, const auto& b) { return a.id < b.id; });
    // The confirmation threshold may differ from the one the map was made with.
    for (StaircaseLandmark& lm : state_.staircases) {
        lm.confirmed = isConfirmed(lm, params_);
    }
    refreshFloors();
}

LandmarkUpdate LandmarkMap::addDetection(const Staircase& detection_world, double stamp_s) {
    LandmarkUpdate update;
    const std::optional<Staircase> canonical = canonicalStaircase(detection_world);
    if (!canonical || !std::isfinite(stamp_s)) {
        update.changed = false;
        return update;
    }
    std::vector<int> matches;  // indices, ascending id because staircases are ordered by id
    for (std::size_t i = 0; i < state_.staircases.size(); ++i) {
        if (sameStaircase(state_.staircases[i].stairs, *canonical, params_))
            matches.push_back(static_cast<int>(i));
    }
    int index = 0;
    if (matches.empty()) {
        index = createLandmark(*canonical, stamp_s);
        update.created = true;
    } else {
        index = matches.front();
        fuseDetection(index, *canonical);
        // A detection that bridges landmarks joins them into the oldest (lowest id).
        for (auto it = matches.rbegin(); it + 1 != matches.rend(); ++it) {
            update.absorbed_ids.push_back(state_.staircases[*it].id);
            joinInto(index, *it);
        }
    }
    StaircaseLandmark& lm = state_.staircases[index];
    lm.observations += 1;
    if (detection_world.direction == StairDirection::Ascending) lm.bottom_observed = true;
    if (detection_world.direction == StairDirection::Descending) lm.top_observed = true;
    lm.first_seen_s = std::min(lm.first_seen_s, stamp_s);
    lm.last_seen_s = std::max(lm.last_seen_s, stamp_s);
    joinOverlappingLandmarks(index, update);
    update.merged_landmarks = !update.absorbed_ids.empty();
    std::sort(update.absorbed_ids.begin(), update.absorbed_ids.end());
    for (StaircaseLandmark& l : state_.staircases) {
        l.confirmed = isConfirmed(l, params_);
    }
    refreshFloors();
    return update;
}

int LandmarkMap::createLandmark(const Staircase& canonical, double stamp_s) {
    StaircaseLandmark lm;
    lm.id = state_.next_landmark_id++;
    lm.stairs = canonical;
    lm.step_observations.assign(canonical.steps.size(), 1);
    lm.first_seen_s = stamp_s;
    lm.last_seen_s = stamp_s;
    state_.staircases.push_back(std::move(lm));
    return static_cast<int>(state_.staircases.size()) - 1;
}

void LandmarkMap::fuseDetection(int index, const Staircase& canonical) {
    const WeightedStaircase det{canonical, std::vector<int>(canonical.steps.size(), 1)};
    mergeInto(state_.staircases[index], det, params_);
}

int LandmarkMap::joinInto(int keep_index, int absorb_index) {
    StaircaseLandmark absorbed = state_.staircases[absorb_index];
    StaircaseLandmark& keep = state_.staircases[keep_index];
    mergeInto(keep, weighted(absorbed), params_);
    keep.observations += absorbed.observations;
    keep.bottom_observed = keep.bottom_observed || absorbed.bottom_observed;
    keep.top_observed = keep.top_observed || absorbed.top_observed;
    keep.first_seen_s = std::min(keep.first_seen_s, absorbed.first_seen_s);
    keep.last_seen_s = std::max(keep.last_seen_s, absorbed.last_seen_s);
    for (auto& [gone, into] : state_.absorbed) {
        if (into == absorbed.id) into = keep.id;
    }
    state_.absorbed[absorbed.id] = keep.id;
    state_.staircases.erase(state_.staircases.begin() + absorb_index);
    return absorb_index < keep_index ? keep_index - 1 : keep_index;
}

void LandmarkMap::joinOverlappingLandmarks(int index, LandmarkUpdate& update) {
    // Fusion may grow a landmark until it overlaps another one: join those too.
    for (bool joined = true; joined;) {
        joined = false;
        for (int j = 0; j < static_cast<int>(state_.staircases.size()); ++j) {
            if (j == index ||
                !sameStaircase(state_.staircases[index].stairs, state_.staircases[j].stairs,
                               params_))
                continue;
            const int keep = std::min(index, j), absorb = std::max(index, j);
            update.absorbed_ids.push_back(state_.staircases[absorb].id);
            index = joinInto(keep, absorb);
            joined = true;
            break;
        }
    }
    update.landmark_id = state_.staircases[index].id;
}

bool LandmarkMap::addRobotFloor(double floor_z, double stamp_s) {
    (void)stamp_s;  // kept for symmetry with addDetection and future decay of old samples
    if (!std::isfinite(floor_z)) return false;
    const std::vector<int> before = floorSnapshot();
    addRobotFloorSample(state_, floor_z, params_);
    refreshFloors();
    return floorSnapshot() != before;
}

bool LandmarkMap::addFloorTransit(const FloorTransit& transit) {
    if (transit.floor_path.size() < 3 || !std::isfinite(transit.stamp_s)) return false;
    for (const Eigen::Vector3d& p : transit.floor_path) {
        if (!p.allFinite()) return false;
    }
    const std::vector<int> before = floorSnapshot();
    state_.transits.push_back(transit);
    // Bounded (repeated runs over one building keep adding climbs): the oldest go first.
    constexpr std::size_t kMaxTransits = 256;
    if (state_.transits.size() > kMaxTransits) state_.transits.erase(state_.transits.begin());
    refreshFloors();
    return floorSnapshot() != before;
}

std::vector<int> LandmarkMap::floorSnapshot() const {
    std::vector<int> ids;
    for (const Floor& f : floors()) ids.push_back(f.id);
    for (const StaircaseLandmark& lm : state_.staircases) {
        ids.push_back(lm.bottom_floor);
        ids.push_back(lm.top_floor);
    }
    return ids;
}

std::vector<Floor> LandmarkMap::floors() const {
    std::vector<Floor> out;
    for (const Floor& f : state_.floor_levels) {
        if (isReported(f)) out.push_back(f);
    }
    std::sort(out.begin(), out.end(), [](const Floor& a, const Floor& b) { return a.z < b.z; });
    return out;
}

const StaircaseLandmark* LandmarkMap::find(int id) const {
    const auto alias = state_.absorbed.find(id);
    if (alias != state_.absorbed.end()) id = alias->second;
    for (const StaircaseLandmark& lm : state_.staircases) {
        if (lm.id == id) return &lm;
    }
    return nullptr;
}

void LandmarkMap::refreshFloors() { refreshFloorLevels(state_, params_); }

bool LandmarkMap::isReported(const Floor& floor) const { return isReportedFloor(floor, params_); }

}  // namespace stairmap
