#pragma once
// Test helpers: canonical staircase landmarks with known geometry, flat floors as voxel centres.

#include <cmath>
#include <vector>

#include "core/PointCloud.h"
#include "map/LandmarkTypes.h"

namespace stairmap::test {

struct FlightSpec {
    Eigen::Vector3d foot = Eigen::Vector3d::Zero();  ///< [m] bottom centre of the first riser
    double heading_rad = 0.0;                        ///< uphill
    double rise = 0.17, run = 0.28, width = 1.0;     ///< [m]
    int risers = 10;
    int landing_after = -1;       ///< a mid landing after this many risers (-1: none)
    double landing_length = 1.2;  ///< [m] nosing-to-next-riser spacing at the landing
};

/// A confirmed canonical landmark: nosing k (0-based) at foot + along * (k * run, plus the landing)
/// + z * (k + 1) * rise; edges start on the left facing uphill (core/Staircase.h).
inline StaircaseLandmark makeLandmark(int id, const FlightSpec& f, int bottom_floor,
                                      int top_floor) {
    StaircaseLandmark lm;
    lm.id = id;
    const Eigen::Vector3d along(std::cos(f.heading_rad), std::sin(f.heading_rad), 0.0);
    const Eigen::Vector3d left(-along.y(), along.x(), 0.0);
    double x = 0.0;
    for (int k = 0; k < f.risers; ++k) {
        if (k > 0) x += (k == f.landing_after ? f.landing_length : f.run);
        const Eigen::Vector3d c = f.foot + x * along + Eigen::Vector3d(0, 0, (k + 1) * f.rise);
        StairEdge e;
        e.start = c + 0.5 * f.width * left;
        e.end = c - 0.5 * f.width * left;
        e.num_points = 50;
        lm.stairs.steps.push_back(e);
        lm.step_observations.push_back(3);
    }
    lm.stairs.step_height = f.rise;
    lm.stairs.step_depth = f.run;
    lm.stairs.step_width = f.width;
    lm.stairs.slope_rad = std::atan2(f.rise, f.run);
    lm.stairs.heading_rad = f.heading_rad;
    lm.stairs.location = lm.stairs.steps.front().centre();
    lm.confirmed = true;
    lm.observations = 5;
    lm.first_seen_s = 10.0;
    lm.last_seen_s = 42.0;
    lm.bottom_observed = lm.top_observed = true;
    lm.bottom_floor = bottom_floor;
    lm.top_floor = top_floor;
    return lm;
}

inline Floor makeFloor(int id, double z) {
    Floor f;
    f.id = id;
    f.z = z;
    f.robot_samples = 10;
    return f;
}

/// Voxel centres (5 cm) of a level floor over [x0, x1] x [y0, y1] at height z.
inline void addFloorVoxels(PointCloud& cloud, double x0, double x1, double y0, double y1, double z,
                           double res = 0.05) {
    for (double x = x0 + 0.5 * res; x < x1; x += res) {
        for (double y = y0 + 0.5 * res; y < y1; y += res) {
            cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                               static_cast<float>(z + 0.5 * res));
        }
    }
}

/// Voxel centres filling a box (an obstacle).
inline void addBoxVoxels(PointCloud& cloud, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                         double res = 0.05) {
    for (double x = lo.x() + 0.5 * res; x < hi.x(); x += res) {
        for (double y = lo.y() + 0.5 * res; y < hi.y(); y += res) {
            for (double z = lo.z() + 0.5 * res; z < hi.z(); z += res) {
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(z));
            }
        }
    }
}

}  // namespace stairmap::test
