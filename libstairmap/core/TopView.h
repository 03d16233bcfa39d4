#pragma once
// Pre-processing, paper Sec. III-A, first step: voxel grid + top view. For every XY column of
// leaf x leaf metres only the highest point is kept, so vertical planes (risers, walls) collapse
// onto their top edge.
// Then every column is classified against its radial neighbours (towards / away from the robot):
// a nosing is where the surface drops by more than edge_min_dz_m (or ends). Empty columns (holes
// of a sparse or coarse cloud, the rows of a far depth-camera tread) are skipped when looking for
// the neighbour, up to neighbour_walk_m (default 20 cm, at most 8 columns); none within it counts
// as a drop.

#include <cstdint>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap {

enum TopViewFlag : std::uint8_t {
    kFrontDrop = 1,  ///< the neighbour towards the robot is lower or empty (ascending nosing)
    kBackDrop = 2,   ///< the neighbour away from the robot is lower or empty (descending nosing)
};

struct TopViewCell {
    float x, y, z;        ///< [m] the highest point of the column
    std::uint8_t flags;   ///< TopViewFlag bits
};

/// [-] longest neighbour walk in columns (also the grid's padding)
constexpr int kMaxNeighbourWalk = 8;

struct TopViewParams {
    double leaf_m = 0.025;      ///< [m] column size
    double max_range_m = 10.0;  ///< [m] XY range limit
    double z_lo = -3.0;         ///< [m] points below are ignored
    double z_hi = 3.0;          ///< [m] points above are ignored (ceilings)
    double edge_min_dz_m = 0.05;  ///< [m] drop that makes a column a nosing candidate
    /// [m] a candidate whose neighbour on the other side is higher than this is a riser top
    /// just below the nosing (points spilled by noise) and is not a nosing
    double edge_spill_dz_m = 0.025;
    double edge_spill_max_dz_m = 0.11;  ///< [m] ...and lower than this (higher: a wall, a floor)
    /// [m] how far along the ray a neighbour is looked for; none within it = empty = a drop
    /// (rounded to whole columns, 1 to kMaxNeighbourWalk)
    double neighbour_walk_m = 0.20;
    /// [m] ground band (floor +- tolerance): only the descending (back-drop) flag is computed there,
    /// for the floor's own nosing; ascending nosings are never at floor level.
    double ground_z_lo = 0.0;
    double ground_z_hi = 0.0;
};

/// Builds the top view of `cloud` (robot frame, robot at the XY origin) and writes the columns that
/// are nosing candidates (flags != 0) into `cells`, which is cleared first. Non-finite points are ignored.
/// Cost: two passes over the cloud plus one over a flat XY array spanning the points' bounding box
/// cropped to +-max_range_m (no hashing, no sorting of points). Memory: that array, 8 bytes per
/// leaf x leaf column, at most (2 max_range_m / leaf_m + 10)^2 x 8 bytes whatever the cloud
/// (DetectorParams::validate bounds it by kMaxTopViewGridBytes), plus 16 bytes per candidate.
void buildTopView(const PointCloud& cloud, const TopViewParams& params,
                  std::vector<TopViewCell>& cells);

}  // namespace stairmap
