#pragma once
// One benchmark sample from the random generator: the drawn scene observed by its sensor (scans
// accumulated along a short path, or an elevation map), with the truth in the robot frame.
//
// Which flights count: a nosing is "seen" when at least kSeenPoints points lie on its tread or the
// riser below it. A flight with >= 4 seen nosings (the detector's minimum) is expected (seen_as
// set: ascending, or descending when seen from its top floor); with <= 1 it is out of view and not
// expected; with 2-3 (half in view: neither fair to demand nor to punish) the scene is redrawn
// (attempt 1, 2, ... of the same index and family), at most max_attempts times.

#include <Eigen/Geometry>
#include <vector>

#include "core/GroundTruth.h"
#include "core/PointCloud.h"
#include "sim/RandomScene.h"
#include "sim/Scene.h"
#include "sim/SensorModel.h"

namespace stairmap::sim {

constexpr int kSeenPoints = 5;   ///< points that make a nosing seen
constexpr int kExpectedNosings = 4;  ///< seen nosings that make a flight expected

struct RandomCloud {
    RandomSceneSpec spec;            ///< the accepted description
    PointCloud cloud;                ///< [m] robot frame (gravity aligned, floor at -base height)
    SceneTruth truth;                ///< robot frame; observer_floor_z = -base height
    std::vector<int> seen_nosings;   ///< per truth staircase
    int attempts = 1;                ///< descriptions drawn for this index
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
};

/// Sensor model for a spec (presets, kept small for a 2-core machine: <= ~66k beams per scan,
/// 25 m range, 2 % dropouts). Elevation maps have no sensor model (type is unused).
SensorParams randomSensorParams(const SensorSpec& sensor);
/// Mount: mount_height_m above the robot origin, pitched down by pitch_deg.
Eigen::Isometry3d randomSensorMount(const SensorSpec& sensor);

/// Points in the final robot frame: scans along the path (each with body roll/pitch and its true
/// pose), or the elevation map (one point per cell on the top surface within 4 m, 3 mm noise).
PointCloud observeRandomScene(const Scene& scene, const RandomSceneSpec& spec);

/// Seen nosings of each staircase of `truth` (same frame as `cloud`).
std::vector<int> seenNosings(const SceneTruth& truth, const PointCloud& cloud);

/// Draws, builds and observes scene `index` of set `seed` (see the redraw rule above).
RandomCloud makeRandomCloud(std::uint64_t seed, int index, const RandomRanges& ranges = {},
                            int max_attempts = 6);

}  // namespace stairmap::sim
