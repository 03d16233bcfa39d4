#pragma once
// Ground truth of simulated scenes: the true geometry of every staircase and the floors' heights.
// Shared by the simulator (which produces it) and the evaluation (which scores detections against it).
//
// Nosing convention (the detector uses the same one): a nosing is the horizontal edge where a tread,
// or the upper floor/landing, meets the top of the riser below it, at the tread's height. A staircase
// with N risers has N nosings, stored bottom to top; the last one is the upper floor's edge.

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/Staircase.h"

namespace stairmap {

/// The five staircase categories of the paper's Tables I/II, plus scenes that contain no staircase.
enum class StairKind { Ascending, Hollow, Spiral, Descending, Debris, Negative };

/// Lower-case name used in files and tables ("ascending", ..., "negative").
std::string stairKindName(StairKind kind);
/// Inverse of stairKindName; std::nullopt for an unknown name.
std::optional<StairKind> stairKindFromName(const std::string& name);

/// One nosing: a horizontal segment [m].
struct NosingSegment {
    Eigen::Vector3d start = Eigen::Vector3d::Zero();
    Eigen::Vector3d end = Eigen::Vector3d::Zero();
    Eigen::Vector3d centre() const { return 0.5 * (start + end); }
};

struct StaircaseTruth {
    std::string name;                     ///< unique within a scene, e.g. "stair_a"
    StairKind kind = StairKind::Ascending;
    std::vector<NosingSegment> nosings;   ///< bottom to top; size() == num_risers
    double rise_m = 0.0;                  ///< [m] riser height
    double run_m = 0.0;  ///< [m] tread depth (spiral: chord between consecutive nosing centres)
    double width_m = 0.0;                 ///< [m] nosing length
    int num_risers = 0;
    double bottom_z = 0.0;                ///< [m] height of the floor at the foot of the flight
    double top_z = 0.0;                   ///< [m] height of the floor/landing at its head
    /// How the observer sees it (single clouds only): ascending when the observer stands on the
    /// bottom floor, descending when on the top floor; unset for world-frame sequences.
    std::optional<StairDirection> seen_as;
};

/// Everything true about a scene, in one frame (world for sequences, robot for single clouds).
struct SceneTruth {
    std::string frame = "world";          ///< "world" or "robot"
    std::vector<StaircaseTruth> staircases;
    std::vector<double> floor_heights;    ///< [m] heights of the walkable floors, ascending
    /// Single clouds: floor the robot stands on, in the robot frame [m] (= -base height).
    std::optional<double> observer_floor_z;
};

/// Returns `truth` with every position expressed in frame B, given T_b_a (a = truth's frame).
/// Heights change only by the translation's z (T_b_a must keep gravity along z).
SceneTruth transformTruth(const SceneTruth& truth, const Eigen::Isometry3d& T_b_a,
                          const std::string& frame_b);

}  // namespace stairmap
