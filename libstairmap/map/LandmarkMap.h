#pragma once
// Persistent multi-floor staircase landmark map (issue 4, items 4 "Landmarks/Floors").
// Detections, already transformed into the world frame, are associated with existing landmarks
// (paper Definition 2 on any step pair, overlapping footprints, or one continuing the other), merged
// by the core's Algorithm 2 (core/StaircaseMerge.h: mergeCanonical, covariance-weighted line fusion),
// and unmatched ones start new landmarks with new IDs.
// Floors are height clusters of where the robot drove plus staircase ends; each staircase links
// the floor it leaves from to the floor it reaches.

#include <vector>

#include "core/Staircase.h"
#include "map/LandmarkParams.h"
#include "map/LandmarkTypes.h"

namespace stairmap {

/// What one addDetection() did.
struct LandmarkUpdate {
    int landmark_id = -1;           ///< landmark the detection went to (after any joining)
    bool created = false;           ///< a new landmark was started
    bool merged_landmarks = false;  ///< the detection bridged landmarks that were joined
    std::vector<int> absorbed_ids;  ///< landmarks joined into landmark_id (now retired)
    bool changed = true;            ///< the map changed (false only for rejected detections)
};

class LandmarkMap {
public:
    /// Throws std::invalid_argument naming the field if a parameter is out of range.
    explicit LandmarkMap(const LandmarkParams& params = {});
    /// Continues a saved map (see io/json/LandmarkJson.h). Throws std::invalid_argument if the state is
    /// inconsistent (duplicate ids, ids >= next id, non-finite numbers, empty staircases).
    LandmarkMap(LandmarkMapState state, const LandmarkParams& params);

    /// Adds one detection in the WORLD frame, ascending or descending (canonicalised inside).
    /// A detection with no steps or non-finite coordinates is rejected (changed = false).
    /// Cost: O(landmarks x steps^2).
    LandmarkUpdate addDetection(const Staircase& detection_world, double stamp_s);

    /// Adds the height of the floor under the robot [m, world z] (e.g. robot z minus its height
    /// above ground). Returns true if the set of reported floors or a staircase's floors changed.
    bool addRobotFloor(double floor_z, double stamp_s);

    /// Adds a climb or descent of the robot between two floor levels (see FloorTransit); a flight
    /// it went through is linked to both floors (map/StaircaseTraversal.h). Paths with fewer than
    /// 3 samples or non-finite ones are ignored; the latest 256 are kept. Returns true if a
    /// staircase's floors changed.
    bool addFloorTransit(const FloorTransit& transit);

    /// Landmarks ordered by id.
    const std::vector<StaircaseLandmark>& staircases() const { return state_.staircases; }
    /// Reported floors (enough robot samples, or a staircase end), ordered by height.
    std::vector<Floor> floors() const;
    /// The landmark with this id (following absorbed ids to the survivor), nullptr if none.
    const StaircaseLandmark* find(int id) const;

    const LandmarkMapState& state() const { return state_; }
    const LandmarkParams& params() const { return params_; }

private:
    int createLandmark(const Staircase& canonical, double stamp_s);  ///< returns its index
    void fuseDetection(int index, const Staircase& canonical);
    int joinInto(int keep_index, int absorb_index);
    void joinOverlappingLandmarks(int index, LandmarkUpdate& update);
    void refreshFloors();
    std::vector<int> floorSnapshot() const;  ///< reported floor ids, then each staircase's links
    bool isReported(const Floor& floor) const;

    LandmarkParams params_;
    LandmarkMapState state_;
};

}  // namespace stairmap
