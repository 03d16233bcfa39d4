#include "fleetlive/LiveFleetMap.h"

#include <stdexcept>

#include "map/LandmarkMap.h"

namespace stairmap::fleetlive {

LiveFleetMap::LiveFleetMap(std::size_t robots, const LandmarkParams& landmark_params,
                           const fleet::AlignmentParams& alignment_params)
    : landmark_params_(landmark_params), alignment_params_(alignment_params), maps_(robots), status_(robots) {
    if (robots == 0) throw std::invalid_argument("fleet: no robot");
}

void LiveFleetMap::update(std::size_t robot, LandmarkMapState state) {
    if (robot >= maps_.size()) throw std::out_of_range("fleet: robot index " + std::to_string(robot));
    LandmarkMap check(state, landmark_params_);  // throws for an inconsistent map, before any change
    status_[robot].has_map = true;
    status_[robot].landmarks = state.staircases.size();
    maps_[robot] = std::move(state);
    rebuild();
}

namespace {
/// MapFusion numbers maps in the order they were added; the fleet names them by robot index.
std::vector<fleet::LandmarkProvenance> byRobot(std::vector<fleet::LandmarkProvenance> provenance,
                                               const std::vector<std::size_t>& robot_of_map) {
    for (auto& landmark : provenance) {
        for (auto& c : landmark.sources) c.map = static_cast<int>(robot_of_map.at(c.map));
        for (auto& step : landmark.steps)
            for (auto& c : step) c.map = static_cast<int>(robot_of_map.at(c.map));
    }
    return provenance;
}
}  // namespace

void LiveFleetMap::rebuild() {
    fleet_ = LandmarkMapState{};
    provenance_.clear();
    for (RobotStatus& s : status_) s.in_fleet_map = false;
    if (!maps_[0]) {
        for (std::size_t r = 1; r < maps_.size(); ++r)
            status_[r].note = "waiting for the first robot's map (it sets the fleet frame)";
        return;
    }
    fleet::MapFusion fusion(*maps_[0], landmark_params_);
    status_[0].in_fleet_map = true;
    status_[0].T_fleet_robot = fleet::Transform4{};
    status_[0].note = "sets the fleet frame";
    std::vector<std::size_t> robot_of_map{0};
    for (std::size_t r = 1; r < maps_.size(); ++r) {
        RobotStatus& s = status_[r];
        if (!maps_[r]) continue;
        const fleet::AlignmentResult a = fleet::estimateAlignment(fusion.state(), *maps_[r], alignment_params_);
        if (a.status == fleet::AlignmentStatus::Aligned) {
            s.T_fleet_robot = a.T_first_other;
            s.sigma = a.sigma;
            s.pairs = a.pairs;
            s.note = "aligned on " + std::to_string(a.pairs.size()) + " shared staircase(s)";
        } else if (s.T_fleet_robot) {
            s.note = "kept the last alignment (" + a.reason + ")";
        } else {
            s.note = "not aligned yet: " + a.reason;
            continue;
        }
        robot_of_map.resize(static_cast<std::size_t>(fusion.add(*maps_[r], *s.T_fleet_robot)) + 1);
        robot_of_map.back() = r;
        s.in_fleet_map = true;
    }
    fleet_ = fusion.state();
    provenance_ = byRobot(fusion.provenance(), robot_of_map);
}

}  // namespace stairmap::fleetlive
