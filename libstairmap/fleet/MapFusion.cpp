#include "fleet/MapFusion.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/StaircaseMerge.h"
#include "core/StaircaseTransform.h"
#include "map/LandmarkMap.h"
#include "map/StaircaseAssociation.h"

namespace stairmap::fleet {
namespace {

/// [m] a source step counts for a fused step when its centre is this close to the fused line.
constexpr double kStepProvenanceDistance = 0.15;

double lineDistance(const StairEdge& line, const Eigen::Vector3d& p) {
    const Eigen::Vector2d d = (line.end - line.start).head<2>();
    if (d.norm() < 1e-9) return (p - line.start).head<2>().norm();
    const Eigen::Vector2d n(-d.y() / d.norm(), d.x() / d.norm());
    return std::abs(n.dot((p - line.start).head<2>()));
}

}  // namespace

MapFusion::MapFusion(LandmarkMapState first, const LandmarkParams& params)
    : params_(params), state_(std::move(first)) {
    refresh();
    for (const StaircaseLandmark& lm : state_.staircases) {
        sources_.push_back(
            {lm.id, Source{0, lm.id, lm.observations, lm.stairs, lm.step_observations}});
    }
}

int MapFusion::add(const LandmarkMapState& other, const Transform4& T_first_this) {
    const int index = maps_++;
    const Eigen::Isometry3d T = T_first_this.isometry();
    for (const StaircaseLandmark& lm : other.staircases) {
        if (lm.stairs.steps.empty()) continue;
        StaircaseLandmark moved = lm;
        moved.stairs = transformStaircase(lm.stairs, T);  // stays canonical: yaw keeps left/right
        addLandmark(moved, Source{index, lm.id, lm.observations, moved.stairs, lm.step_observations});
    }
    addFloors(other, T_first_this);
    refresh();
    return index;
}

void MapFusion::addLandmark(const StaircaseLandmark& moved, const Source& source) {
    for (StaircaseLandmark& lm : state_.staircases) {
        if (!sameStaircase(lm.stairs, moved.stairs, params_)) continue;
        // Algorithm 2 on the two flights, weighted by their per-step observation counts.
        const auto merged = mergeCanonical({lm.stairs, lm.step_observations},
                                           {moved.stairs, moved.step_observations},
                                           toMergeParams(params_), StepAnchor::AssociatedElsewhere);
        lm.stairs = merged->stairs;
        lm.step_observations = merged->step_observations;
        lm.observations += moved.observations;
        lm.bottom_observed = lm.bottom_observed || moved.bottom_observed;
        lm.top_observed = lm.top_observed || moved.top_observed;
        lm.first_seen_s = std::min(lm.first_seen_s, moved.first_seen_s);
        lm.last_seen_s = std::max(lm.last_seen_s, moved.last_seen_s);
        sources_.push_back({lm.id, source});
        return;
    }
    StaircaseLandmark created = moved;
    created.id = state_.next_landmark_id++;
    created.bottom_floor = created.top_floor = -1;  // re-linked by refresh()
    sources_.push_back({created.id, source});
    state_.staircases.push_back(std::move(created));
}

void MapFusion::addFloors(const LandmarkMapState& other, const Transform4& T) {
    for (const Floor& f : other.floor_levels) {
        if (f.robot_samples == 0) continue;  // staircase ends are re-derived from the landmarks
        Floor moved;
        moved.id = state_.next_floor_id++;
        moved.z = f.z + T.z;
        moved.robot_samples = f.robot_samples;
        moved.robot_z_sum = f.robot_z_sum + T.z * f.robot_samples;
        state_.floor_levels.push_back(moved);
    }
    const Eigen::Isometry3d iso = T.isometry();
    for (const FloorTransit& t : other.transits) {
        FloorTransit moved = t;
        for (Eigen::Vector3d& p : moved.floor_path) p = iso * p;
        state_.transits.push_back(std::move(moved));
    }
}

void MapFusion::refresh() {
    // LandmarkMap validates, re-derives confirmation and floors (levels closer than the
    // tolerance merge, keeping the lower id) and links every flight to its floors.
    state_ = LandmarkMap(std::move(state_), params_).state();
}

std::vector<std::vector<Contribution>> MapFusion::stepProvenance(
    const StaircaseLandmark& lm, const std::vector<Source>& srcs) const {
    const double half_rise = 0.5 * (lm.stairs.step_height > 0.01 ? lm.stairs.step_height : 0.15);
    std::vector<std::vector<Contribution>> steps;
    for (const StairEdge& fused : lm.stairs.steps) {
        std::map<int, int> per_map;
        for (const Source& s : srcs) {
            for (std::size_t i = 0; i < s.stairs.steps.size(); ++i) {
                const StairEdge& e = s.stairs.steps[i];
                if (std::abs(e.centre().z() - fused.centre().z()) <= half_rise &&
                    lineDistance(fused, e.centre()) <= kStepProvenanceDistance)
                    per_map[s.map] += s.step_observations[i];
            }
        }
        std::vector<Contribution> entry;
        for (const auto& [map, count] : per_map) entry.push_back({map, -1, count});
        steps.push_back(std::move(entry));
    }
    return steps;
}

std::vector<LandmarkProvenance> MapFusion::provenance() const {
    std::vector<LandmarkProvenance> out;
    for (const StaircaseLandmark& lm : state_.staircases) {
        LandmarkProvenance p;
        p.id = lm.id;
        std::vector<Source> srcs;
        for (const auto& [id, s] : sources_) {
            if (id != lm.id) continue;
            srcs.push_back(s);
            p.sources.push_back({s.map, s.source_id, s.observations});
        }
        p.steps = stepProvenance(lm, srcs);
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace stairmap::fleet
