#pragma once
// Synthetic landmark maps with known geometry for the fleet tests: straight and spiral flights
// built nosing by nosing (truth known independently of the code under test), moved into another
// robot's frame by a known transform, with seeded noise.

#include <cmath>
#include <random>
#include <vector>

#include "core/StaircaseCanonical.h"
#include "core/StaircaseTransform.h"
#include "fleet/Transform4.h"
#include "map/LandmarkTypes.h"

namespace stairmap::fleet::test {

struct FlightSpec {
    Eigen::Vector2d foot = Eigen::Vector2d::Zero();  ///< [m] xy of nosing level 0 (the floor edge)
    double heading_deg = 0.0;  ///< uphill direction (straight) / start angle (spiral)
    double floor_z = 0.0;      ///< [m]
    double rise = 0.18, run = 0.28, width = 1.1;  ///< [m]
    int first_level = 1, last_level = 8;          ///< nosings seen (1 = first above the floor)
    double spiral_turn_deg = 0.0;  ///< != 0: a spiral around `foot` turning this much per step
    bool bottom_observed = false, top_observed = false;
};

inline StairEdge edgeAt(const FlightSpec& f, int level) {
    const double z = f.floor_z + level * f.rise;
    StairEdge e;
    if (f.spiral_turn_deg != 0.0) {  // radial nosing from 0.2 m to 0.2 m + width
        const double a = (f.heading_deg + level * f.spiral_turn_deg) * M_PI / 180.0;
        const Eigen::Vector2d r(std::cos(a), std::sin(a));
        e.start << f.foot + 0.2 * r, z;
        e.end << f.foot + (0.2 + f.width) * r, z;
        return e;
    }
    const double h = f.heading_deg * M_PI / 180.0;
    const Eigen::Vector2d u(std::cos(h), std::sin(h)), left(-u.y(), u.x());
    const Eigen::Vector2d c = f.foot + (level - 1) * f.run * u;
    e.start << c + 0.5 * f.width * left, z;
    e.end << c - 0.5 * f.width * left, z;
    return e;
}

inline StaircaseLandmark makeLandmark(const FlightSpec& f, int id, std::mt19937* noise = nullptr,
                                      double sigma_m = 0.0) {
    Staircase s;
    std::normal_distribution<double> n(0.0, sigma_m);
    for (int l = f.first_level; l <= f.last_level; ++l) {
        StairEdge e = edgeAt(f, l);
        if (noise) {
            e.start += Eigen::Vector3d(n(*noise), n(*noise), 0.0);
            e.end += Eigen::Vector3d(n(*noise), n(*noise), 0.0);
            const double dz = 0.3 * n(*noise);
            e.start.z() += dz;
            e.end.z() += dz;
        }
        e.num_points = 50;
        s.steps.push_back(e);
    }
    s.step_height = f.rise;
    s.step_depth = f.run;
    s.heading_rad = f.heading_deg * M_PI / 180.0;
    StaircaseLandmark lm;
    lm.id = id;
    lm.stairs = *canonicalStaircase(s);
    lm.step_observations.assign(lm.stairs.steps.size(), 2);
    lm.observations = 3;
    lm.confirmed = true;
    lm.bottom_observed = f.bottom_observed;
    lm.top_observed = f.top_observed;
    return lm;
}

inline LandmarkMapState makeMap(const std::vector<StaircaseLandmark>& landmarks) {
    LandmarkMapState state;
    state.staircases = landmarks;
    for (const auto& lm : landmarks) state.next_landmark_id = std::max(state.next_landmark_id, lm.id + 1);
    return state;
}

/// The map as robot "other" holds it: every landmark moved by T_first_other^-1.
inline LandmarkMapState inOtherFrame(LandmarkMapState state, const Transform4& T_first_other) {
    const Eigen::Isometry3d T_other_first = T_first_other.isometry().inverse();
    for (auto& lm : state.staircases) lm.stairs = transformStaircase(lm.stairs, T_other_first);
    for (auto& f : state.floor_levels) {
        f.z -= T_first_other.z;
        f.robot_z_sum -= T_first_other.z * f.robot_samples;
    }
    return state;
}

inline double yawErrorDeg(double a_rad, double b_rad) {
    return std::abs(wrapAngle(a_rad - b_rad)) * 180.0 / M_PI;
}

}  // namespace stairmap::fleet::test
