#pragma once
// The fleet map kept while robots publish their own maps (issue 13, item 2; `stairmap fleet`):
// each robot's latest map (in its own frame) is kept, so a robot that goes silent keeps its
// landmarks and one that restarts replaces them. The fleet frame is the first robot's. On every
// change the fleet map is rebuilt: the first robot's map, then each other robot in order, aligned
// to the fleet map so far (fleet/MapAlignment.h, 4 DoF from shared staircases) and fused
// (fleet/MapFusion.h). A robot that cannot be aligned now keeps the transform found last time;
// one never aligned waits outside the fleet map (its status says why). Pure logic: no DDS.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fleet/AlignmentParams.h"
#include "fleet/MapAlignment.h"
#include "fleet/MapFusion.h"
#include "fleet/Transform4.h"
#include "map/LandmarkParams.h"
#include "map/LandmarkTypes.h"

namespace stairmap::fleetlive {

struct RobotStatus {
    bool has_map = false;           ///< a map was received
    std::size_t landmarks = 0;      ///< staircases in its latest map
    bool in_fleet_map = false;      ///< its landmarks are part of the fleet map
    std::optional<fleet::Transform4> T_fleet_robot;  ///< its frame in the fleet frame (once aligned)
    fleet::AlignmentSigma sigma;              ///< of T_fleet_robot (zero for robot 0)
    std::vector<fleet::LandmarkPair> pairs;   ///< (fleet map id, this robot's id) that fixed it
    std::string note;               ///< e.g. "no staircase shared with the fleet map yet"
};

class LiveFleetMap {
public:
    /// `robots` robots; robot 0's frame is the fleet frame.
    LiveFleetMap(std::size_t robots, const LandmarkParams& landmark_params = {},
                 const fleet::AlignmentParams& alignment_params = {});

    /// Replaces robot `robot`'s map and rebuilds the fleet map. Throws std::out_of_range for a
    /// bad index; std::invalid_argument for an inconsistent map (nothing changed then).
    void update(std::size_t robot, LandmarkMapState state);

    const LandmarkMapState& fleetMap() const { return fleet_; }
    const std::vector<RobotStatus>& status() const { return status_; }
    /// Per landmark of fleetMap(), ordered by id; Contribution::map is the ROBOT index.
    const std::vector<fleet::LandmarkProvenance>& provenance() const { return provenance_; }

private:
    void rebuild();
    LandmarkParams landmark_params_;
    fleet::AlignmentParams alignment_params_;
    std::vector<std::optional<LandmarkMapState>> maps_;
    std::vector<RobotStatus> status_;
    LandmarkMapState fleet_;
    std::vector<fleet::LandmarkProvenance> provenance_;
};

}  // namespace stairmap::fleetlive
