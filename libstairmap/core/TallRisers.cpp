#include "core/TallRisers.h"

#include <algorithm>
#include <cmath>

#include "core/TurningFlight.h"

namespace stairmap {
namespace {

/// Points of `cloud` on the vertical strip under `upper`'s line with z in (z_lo, z_hi).
int pointsOnStrip(const PointCloud& cloud, const StairEdge& upper, double z_lo, double z_hi,
                  const TallRiserParams& p) {
    const Eigen::Vector2d a = upper.start.head<2>();
    const Eigen::Vector2d d = upper.end.head<2>() - a;
    const double length = d.norm();
    if (length < 1e-6 || z_hi <= z_lo) return 0;
    const Eigen::Vector2d u = d / length;
    const double t_lo = p.end_margin * length, t_hi = (1.0 - p.end_margin) * length;
    int count = 0;
    for (const Eigen::Vector3f& q : cloud) {
        if (!(q.z() > z_lo && q.z() < z_hi)) continue;  // also drops NaN
        const Eigen::Vector2d w = q.head<2>().cast<double>() - a;
        const double t = w.dot(u);
        if (t < t_lo || t > t_hi) continue;
        if (std::abs(w.x() * u.y() - w.y() * u.x()) <= p.strip_half_width_m) ++count;
    }
    return count;
}

}  // namespace

bool putBackOverTallRiser(const PointCloud& cloud, const Staircase& flight,
                          const TallRiserParams& p) {
    if (flight.direction != StairDirection::Ascending || turningFlight(flight)) return false;
    const auto& steps = flight.steps;
    for (std::size_t k = 1; k + 1 < steps.size(); ++k) {
        const StairEdge &lower = steps[k - 1], &put_back = steps[k], &upper = steps[k + 1];
        if (put_back.num_points > 0 || lower.num_points == 0 || upper.num_points == 0) continue;
        const double z_lo = lower.centre().z() + p.above_lower_m;
        const double z_hi = put_back.centre().z() - p.below_put_back_m;
        if (pointsOnStrip(cloud, upper, z_lo, z_hi, p) >= p.min_points) return true;
    }
    return false;
}

int dropFlightsOverTallRisers(const PointCloud& cloud, std::vector<Staircase>& flights,
                              const TallRiserParams& params) {
    const auto before = flights.size();
    flights.erase(
        std::remove_if(flights.begin(), flights.end(),
                       [&](const Staircase& s) { return putBackOverTallRiser(cloud, s, params); }),
        flights.end());
    return static_cast<int>(before - flights.size());
}

}  // namespace stairmap
