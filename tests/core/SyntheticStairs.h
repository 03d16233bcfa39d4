#pragma once
// Synthetic staircase detections with KNOWN geometry and seeded noise for the landmark tests.

#include <algorithm>
#include <cmath>
#include <random>

#include "core/Staircase.h"

namespace stairmap::test {

/// Ground truth of one straight flight. Edge i (0-based) is the nosing of tread i+1: its centre is
/// at origin_xy + i * run * u (u = uphill unit vector), height floor_z + (i + 1) * rise.
struct FlightTruth {
    Eigen::Vector2d origin_xy = Eigen::Vector2d::Zero();  ///< [m] centre of the lowest nosing
    double floor_z = 0.0;        ///< [m] bottom floor
    double heading_rad = 0.0;    ///< uphill
    double rise = 0.17;          ///< [m]
    double run = 0.28;           ///< [m]
    double width = 1.2;          ///< [m]
    int num_steps = 10;

    Eigen::Vector2d uphill() const { return {std::cos(heading_rad), std::sin(heading_rad)}; }
    Eigen::Vector2d left() const { return {-std::sin(heading_rad), std::cos(heading_rad)}; }
    Eigen::Vector3d edgeCentre(int i) const {
        const Eigen::Vector2d xy = origin_xy + i * run * uphill();
        return {xy.x(), xy.y(), floor_z + (i + 1) * rise};
    }
    double topZ() const { return floor_z + num_steps * rise; }
};

/// How one detection saw the flight.
struct ViewSpec {
    int first = 0;                    ///< lowest edge index seen
    int last = -1;                    ///< highest edge index seen (-1: the top one)
    bool descending = false;          ///< seen from the top (steps top to bottom, heading downhill)
    double crop_left = 0.0;           ///< [m] missing from the left end (partial view)
    double crop_right = 0.0;          ///< [m] missing from the right end
    Eigen::Vector3d drift = Eigen::Vector3d::Zero();  ///< [m] pose drift of the whole detection
    double sigma_perp = 0.0;          ///< [m] perpendicular offset noise per edge
    double sigma_theta = 0.0;         ///< [rad] orientation noise per edge
    double sigma_z = 0.0;             ///< [m] height noise per edge
    double sigma_end = 0.0;           ///< [m] noise of each end point along the edge
};

/// Builds a detection of `truth` as the detector would report it in the world frame. The edges'
/// cov_rho_theta is set from the noise sigmas (about the world origin, rho >= 0 convention).
inline Staircase makeDetection(const FlightTruth& truth, const ViewSpec& view, std::mt19937& rng) {
    std::normal_distribution<double> n01(0.0, 1.0);
    const int last = view.last < 0 ? truth.num_steps - 1 : view.last;
    Staircase s;
    s.direction = view.descending ? StairDirection::Descending : StairDirection::Ascending;
    for (int i = view.first; i <= last; ++i) {
        const Eigen::Vector3d c = truth.edgeCentre(i) + view.drift;
        const double dtheta = view.sigma_theta * n01(rng);
        const Eigen::Vector2d u(std::cos(truth.heading_rad + dtheta), std::sin(truth.heading_rad + dtheta));
        const Eigen::Vector2d l(-u.y(), u.x());
        const Eigen::Vector2d cxy = c.head<2>() + view.sigma_perp * n01(rng) * u;
        const double z = c.z() + view.sigma_z * n01(rng);
        const double half = 0.5 * truth.width;
        const double a = half - view.crop_left + view.sigma_end * n01(rng);
        const double b = -half + view.crop_right + view.sigma_end * n01(rng);
        StairEdge e;
        e.start << cxy + a * l, z;  // left end when facing uphill
        e.end << cxy + b * l, z;
        if (view.descending) std::swap(e.start, e.end);  // facing downhill, left is the other end
        const double sp = std::max(view.sigma_perp, 1e-3), st = std::max(view.sigma_theta, 1e-3);
        Eigen::Vector2d n = u;
        if (cxy.dot(n) < 0) n = -n;
        const Eigen::Vector2d t(-n.y(), n.x());
        Eigen::Matrix2d J;
        J << 1.0, cxy.dot(t), 0.0, 1.0;
        e.cov_rho_theta = J * Eigen::Vector2d(sp * sp, st * st).asDiagonal() * J.transpose();
        e.num_points = 40;
        s.steps.push_back(e);
    }
    if (view.descending) std::reverse(s.steps.begin(), s.steps.end());
    s.heading_rad = truth.heading_rad + (view.descending ? M_PI : 0.0);
    s.step_height = truth.rise;
    s.step_depth = truth.run;
    s.step_width = truth.width;
    s.slope_rad = std::atan2(truth.rise, truth.run);
    s.location = s.steps.front().centre();
    return s;
}

}  // namespace stairmap::test
