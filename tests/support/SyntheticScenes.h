#pragma once
// The tests' one generator of synthetic clouds with known staircase geometry, built on sim/: the
// solids come from the simulator's generators (sim/StairGenerators, oriented sim::Box for furniture,
// ramps, tiers and walls), the truth from their sim::SceneTruth, and the cloud from ray casting the
// scene (sim::Scene::castRay) on a dense angular grid from a viewpoint above the robot, so only
// surfaces a sensor could see give points. Independent of the detector.
// Frame: robot frame (x forward, y left, z up), robot at the origin, floor at z = floor_z.

#include <Eigen/Core>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/GroundTruth.h"
#include "core/PointCloud.h"
#include "sim/Scene.h"

namespace stairmap::test {

/// Lower-case kind name for test names ("ascending", ...).
inline std::string toString(StairKind kind) { return stairKindName(kind); }

struct SceneOptions {
    double floor_z = -0.5;           ///< [m] floor height in the robot frame (= -robot height)
    double noise_m = 0.01;           ///< [m] std. dev. of isotropic Gaussian noise per point
    double spacing_m = 0.010;        ///< [m] sample spacing 3 m from the viewpoint (angular grid)
    double view_height_m = 2.5;      ///< [m] viewpoint above the floor, above the robot's origin
    double floor_half_size_m = 3.5;  ///< [m] floor square around the robot
    double max_range_m = 12.0;       ///< [m] rays end here
    double sparse_from_m = 0.0;      ///< [m] > 0: keep probability (sparse_from/r)^2 beyond it
    unsigned seed = 1;
};

struct StairSpec {
    StairKind kind = StairKind::Ascending;  ///< Ascending, Hollow, Spiral, Descending or Debris
    int num_risers = 6;          ///< [-] ascending: risers up to the landing; descending: down
    double rise_m = 0.17;
    double run_m = 0.28;
    double width_m = 1.2;
    double distance_m = 2.0;     ///< [m] robot -> first nosing (descending: floor edge), along yaw
    double lateral_m = 0.0;      ///< [m] sideways offset of the flight's centre line
    double yaw_rad = 0.0;        ///< direction of travel (up for ascending, down for descending)
    double turn_per_step_rad = 0.10;  ///< spiral only
};

/// Known truth of one staircase, conventions of core/Staircase.h (nosings ordered outward from
/// the robot: bottom to top when ascending, top to bottom when descending).
struct StairTruth {
    bool ascending = true;
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> nosings;
    double rise_m = 0, run_m = 0, width_m = 0, heading_rad = 0;
    Eigen::Vector3d location = Eigen::Vector3d::Zero();  ///< centre of the first nosing
};

/// Accumulates solids into a sim::Scene; cloud() ray-casts it.
class SceneBuilder {
public:
    explicit SceneBuilder(const SceneOptions& options);

    /// Adds a staircase and returns its truth.
    StairTruth addStairs(const StairSpec& spec);
    /// Floor square around the robot, open over a descending flight's stairwell.
    void addFloor();
    /// Box (axis given by yaw) standing on z0: sides and top. Centre in the robot frame.
    void addBox(const Eigen::Vector2d& centre, double yaw, double len, double depth, double z0,
                double height);
    /// Inclined ramp from the floor up at `slope_rad`, length along yaw, plus its top platform.
    void addRamp(double distance, double yaw, double slope_rad, double length, double width);
    /// Table: top at `height`, four legs.
    void addTable(const Eigen::Vector2d& centre, double yaw, double len, double depth, double height);
    /// Stepped platform with tiers of (rise, run) and a deep top; used for stages and bleachers.
    void addTiers(double distance, double yaw, int tiers, double rise, double run, double width,
                  double top_depth);
    /// Vertical wall segment from floor to height (5 cm thick).
    void addWall(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double height);

    /// The ray-cast cloud of everything added so far (computed on first use after a change).
    const PointCloud& cloud() const;

private:
    /// Rectangle of the floor left open over a descending flight, in that flight's frame.
    struct Stairwell {
        Eigen::Isometry3d T_robot_well;  ///< x along the flight (down), y left, origin at the edge
        double length = 0, half_width = 0;
    };
    StairTruth addStraight(const StairSpec& spec);
    StairTruth addSpiral(const StairSpec& spec);
    StairTruth addDescending(const StairSpec& spec);
    void addFloorAround(const Stairwell& well);
    /// Box between min and max in the frame T_robot_frame.
    void addFrameBox(const Eigen::Isometry3d& T_robot_frame, const Eigen::Vector3d& min,
                     const Eigen::Vector3d& max);
    StairTruth truthOf(std::size_t index, bool outward_reversed, double heading_rad) const;

    SceneOptions opt_;
    mutable std::mt19937 rng_;
    sim::Scene scene_;
    std::optional<Stairwell> stairwell_;
    mutable std::optional<PointCloud> cloud_;
};

}  // namespace stairmap::test
