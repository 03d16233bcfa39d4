#pragma once
// Where a robot stands to start a flight, and where it arrives: on the floor, facing the flight,
// with its footprint (plus clearance) clear of obstacles in the floor map.

#include <Eigen/Core>

#include "export/FloorGrid.h"
#include "export/RobotProfile.h"

namespace stairmap::exporting {

struct ApproachPose {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< [m] world, z on the floor surface
    double yaw_rad = 0.0;        ///< facing the flight, counter-clockwise from world +x
    bool checked = false;        ///< a floor map was there to check it against
    bool clear = false;          ///< no occupied cell under the footprint + clearance (if checked)
    bool on_seen_floor = false;  ///< seen floor surface under its footprint (if checked)
};

struct ApproachParams {
    double max_backoff_m = 1.5;  ///< [m] how much farther from the flight it may move to be clear
    /// [m] how far it may slide sideways off the flight's centre line (still facing the flight),
    /// e.g. to keep clear of a wall when the measured flight is off-centre in its stairwell
    double max_lateral_m = 0.3;
};

/// The pose `distance` = footprint_length / 2 + clearance + one cell from `edge_xy` (the foot of
/// the first riser, or the top nosing) along `away` (unit, pointing off the flight), facing
/// back (-away). If that footprint rectangle (inflated by the clearance) covers an occupied cell,
/// or no seen floor lies under the footprint, the pose backs off cell by cell up to max_backoff_m,
/// trying sideways offsets up to max_lateral_m (nearest first) at each distance; the first clear
/// pose on seen floor wins, else the first clear one, else the nearest (clear=false). `grid` may be
/// null (nothing to check: checked=false).
/// Cost: O(backoff cells x lateral cells x footprint cells).
ApproachPose findApproach(const FloorGrid* grid, const Eigen::Vector2d& edge_xy,
                          const Eigen::Vector2d& away, double floor_z, const RobotProfile& robot,
                          const ApproachParams& params = {});

/// True if no Occupied cell centre lies inside the rectangle centred at `centre`, with half sizes
/// (half_length along `axis`, half_width across it).
bool rectangleClear(const FloorGrid& grid, const Eigen::Vector2d& centre,
                    const Eigen::Vector2d& axis, double half_length, double half_width);
/// True if some Free cell centre lies inside that rectangle.
bool rectangleSeesFloor(const FloorGrid& grid, const Eigen::Vector2d& centre,
                        const Eigen::Vector2d& axis, double half_length, double half_width);

}  // namespace stairmap::exporting
