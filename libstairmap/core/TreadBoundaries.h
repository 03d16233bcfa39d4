#pragma once
// Nosings read from the treads themselves (issue 10). The row lines of the cylindrical array
// (paper Sec. III-B) follow the sensor's rows, so a spiral's radial nosings that run along the line
// of sight fall into a few azimuth bins and come out in short pieces or not at all; a depth camera
// over a spiral's foot gives lines on 1-2 of its 4 seen levels (dev6 r0100, r0718), however well
// it shows the wedge treads. Where a view shows the treads as surfaces (a depth camera or LiDAR
// pitched down over them, an elevation map), every nosing is also the boundary, in the top view,
// between two flat patches one rise apart, whatever the direction it is seen from.
//
// On the top surface (HeightGrid: the highest point of every cell, as the paper's top view, but
// coarser), flat patches are grown over neighbouring cells whose heights differ by little, and for
// every pair of touching patches a rise apart, lines are fitted through the midpoints between the
// upper patch's cells and the lower patch's cells they touch: the upper patch's front edge, its
// nosing (and, where a tread ends over a lower one, its side or rim: the spiral search keeps only
// radial lines).

#include <vector>

#include "core/HeightGrid.h"
#include "core/LineSegment.h"

namespace stairmap {

struct TreadBoundaryParams {
    double floor_z = 0.0;  ///< [m] the robot's floor (robot frame)
    /// [m] cells within this of floor_z are one patch, the floor, without growing it (most cells
    /// of a view are floor); 0 = the floor is grown like any patch
    double floor_band_m = 0.05;
    /// [m] neighbouring cells of one patch differ at most this much (a depth camera's noise at
    /// 3 m is about 1.5 cm; a rise is 10 cm or more)
    double max_neighbour_dz_m = 0.03;
    /// [m] ... and from the patch's mean so far: noise at a riser (a depth camera's points spread
    /// along its rays) leaves a ramp of cells between two treads that would join them
    double max_patch_dz_m = 0.04;
    double max_patch_spread_m = 0.02;  ///< [m] std. dev. of a patch's heights (flat: no ramp)
    int min_patch_cells = 6;           ///< [-] smaller patches are clutter or noise
    double min_rise_m = 0.08;          ///< [m] height between a nosing's two patches, from ...
    double max_rise_m = 0.33;          ///< [m] ... to
    int min_line_cells = 4;            ///< [-] fewest boundary midpoints of a line
    double min_line_length_m = 0.20;   ///< [m] shorter boundaries are no nosing
    /// [m] midpoints this close to a hypothesis (a line through two of them) hold it; the line
    /// refitted to them must be as straight (RMS distance)
    double max_line_rms_m = 0.03;
};

/// The nosing lines between flat patches of `surface` (robot frame), at the upper patch's mean
/// height, `num_points` their boundary midpoints. Cost: two passes over the grid's cells (patches
/// grown over the occupied ones, then their boundaries), then a few line hypotheses per boundary.
std::vector<LineSegment> treadBoundaryNosings(const HeightGrid& surface,
                                              const TreadBoundaryParams& params = {});

}  // namespace stairmap
