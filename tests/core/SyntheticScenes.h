#pragma once
// Test-side generator of synthetic point clouds with known staircase geometry. Independent of the
// detector: it samples surfaces (floors, risers, treads, walls, boxes) at a given spacing with
// seeded jitter and Gaussian noise, optional sparsity growing with range.
// Frame: robot frame (x forward, y left, z up), robot at the origin, floor at z = floor_z.

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap::test {

enum class StairKind { Ascending, Hollow, Spiral, Descending, Debris };
std::string toString(StairKind kind);

struct SceneOptions {
    double floor_z = -0.5;           ///< [m]
    double noise_m = 0.01;           ///< [m] std. dev. of isotropic Gaussian noise
    double spacing_m = 0.015;        ///< [m] sample spacing on stair surfaces
    double floor_spacing_m = 0.03;   ///< [m] sample spacing on the floor
    double floor_half_size_m = 3.5;  ///< [m] floor square around the robot
    double sparse_from_m = 0.0;      ///< [m] > 0: keep probability (sparse_from/r)^2 beyond it
    unsigned seed = 1;
};

struct StairSpec {
    StairKind kind = StairKind::Ascending;
    int num_risers = 6;          ///< [-] ascending: risers up to the landing; descending: down
    double rise_m = 0.17;
    double run_m = 0.28;
    double width_m = 1.2;
    double distance_m = 2.0;     ///< [m] robot -> first nosing (descending: floor edge), along yaw
    double lateral_m = 0.0;      ///< [m] sideways offset of the flight's centre line
    double yaw_rad = 0.0;        ///< direction of travel (up for ascending, down for descending)
    double turn_per_step_rad = 0.10;  ///< spiral only
};

/// Known truth of one staircase, conventions of core/Staircase.h (nosings, ordered outward).
struct StairTruth {
    bool ascending = true;
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> nosings;
    double rise_m = 0, run_m = 0, width_m = 0, heading_rad = 0;
    Eigen::Vector3d location = Eigen::Vector3d::Zero();
};

/// Accumulates surfaces into one cloud.
class SceneBuilder {
public:
    explicit SceneBuilder(const SceneOptions& options);

    /// Adds a staircase and returns its truth.
    StairTruth addStairs(const StairSpec& spec);
    /// Floor square around the robot, minus the rectangular holes registered by descending stairs.
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
    /// Vertical wall segment from floor to height.
    void addWall(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double height);

    const PointCloud& cloud() const { return cloud_; }

private:
    struct Hole {
        Eigen::Vector2d origin, axis_u, axis_v;  // robot frame, unit axes
        double len_u, half_v;
    };
    /// Samples the parallelogram origin + s*u + t*v, s,t in [0,1].
    void sampleQuad(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                    const Eigen::Vector3d& v, double spacing);
    void addPoint(const Eigen::Vector3d& p);
    StairTruth addStraight(const StairSpec& spec, bool hollow);
    StairTruth addSpiral(const StairSpec& spec);
    StairTruth addDescending(const StairSpec& spec);
    bool inHole(const Eigen::Vector2d& p) const;

    SceneOptions opt_;
    std::mt19937 rng_;
    PointCloud cloud_;
    std::vector<Hole> holes_;
};

}  // namespace stairmap::test
