#pragma once
// Detection, paper Sec. III-C: Definition 1 (what two edges must satisfy to be consecutive steps)
// and Algorithm 1 (initialise with a pair near the floor, extend upwards), repeated on the remaining
// lines to find several staircases per direction.

#include <limits>
#include <optional>
#include <vector>

#include "core/DetectorParams.h"
#include "core/LineSegment.h"

namespace stairmap {

/// Rise, run and the unit normal (lower -> upper) of a valid stair pair.
struct StairPair {
    double rise = 0.0;           ///< [m]
    double run = 0.0;            ///< [m]
    double overlap = 0.0;        ///< [m] common extent along the edges
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();  ///< XY, from lower towards upper edge
};

/// Definition 1, conditions 1-4 (plus a lateral-overlap check): `upper` is the next step above
/// `lower`. z is "upwards away from the floor" (mirror z for descending).
std::optional<StairPair> checkStairPair(const LineSegment& lower, const LineSegment& upper,
                                        const DetectorParams& params);

/// Definition 1, condition 5: does a line of `sorted_lines` (sorted by z) lie strictly between the
/// two edges, covering at least between_overlap_ratio of their common extent? Lines within the
/// height tolerance of `expected_z` (an unseen nosing's height between edges two steps apart;
/// NaN = none) do not count.
bool hasLineBetween(const std::vector<LineSegment>& sorted_lines, int lower, int upper,
                    const StairPair& pair, const DetectorParams& params,
                    double expected_z = std::numeric_limits<double>::quiet_NaN());

/// Algorithm 1 repeated: staircases found in `sorted_lines` (sorted by z, z measured upwards away
/// from the floor at `floor_z`). Each result lists line indices from the floor outward.
/// `min_first_height` is the lowest allowed height of the first edge above the floor [m].
/// `refused` (debug only, may be null): receives the best chain that ended the search for being
/// shorter than min_steps (when it had two edges or more), and `used` the lines taken by results.
/// `continue_down`: each chain is also continued below its first edge, down to the flight's foot
/// (ascending flights rising from a pit or a landing below the robot's floor); with
/// params.ascend_from_below_floor a nosing at the floor's height the chain stepped over counts
/// towards min_steps, and when the chains from the floor fall short before any is found, the
/// longest chain from lines below the floor that rises above it is taken if it counts.
/// `refused_ties` (may be null): the other chains as long as the refused one (at most 8, in search
/// order): when a nosing's line is split at a bend, its longer piece may start the right chain.
std::vector<std::vector<int>> searchStaircases(const std::vector<LineSegment>& sorted_lines,
                                               double floor_z, double min_first_height,
                                               const DetectorParams& params,
                                               std::vector<int>* refused = nullptr,
                                               std::vector<char>* used = nullptr,
                                               bool continue_down = false,
                                               std::vector<std::vector<int>>* refused_ties = nullptr);

}  // namespace stairmap
