#include "sim/RandomFlightGeometry.h"

#include <array>
#include <cmath>

#include "sim/SceneFurniture.h"

namespace stairmap::sim {

namespace {
constexpr double kDeg = M_PI / 180.0;
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

V2 edgeXY(const FlightSpec& f) {
    return f.distance_m * V2(std::cos(f.bearing_deg * kDeg), std::sin(f.bearing_deg * kDeg));
}

std::array<V2, 4> footprint(const FlightSpec& f, double margin) {
    const Eigen::Isometry3d T = straightFlightFrame(f);
    const double x0 = flightFrontX(f) - margin, x1 = flightBackX(f) + margin;
    const double hw = 0.5 * f.width_m + 0.6 + margin;
    std::array<V2, 4> c;
    int i = 0;
    for (double x : {x0, x1})
        for (double y : {-hw, hw}) c[i++] = (T * V3(x, y, 0.0)).head<2>();
    std::swap(c[2], c[3]);  // counter-clockwise order
    return c;
}

/// Separating-axis test of two convex quads.
bool separated(const std::array<V2, 4>& a, const std::array<V2, 4>& b) {
    for (const auto* poly : {&a, &b}) {
        for (int i = 0; i < 4; ++i) {
            const V2 e = (*poly)[(i + 1) % 4] - (*poly)[i];
            const V2 n(-e.y(), e.x());
            double amin = 1e18, amax = -1e18, bmin = 1e18, bmax = -1e18;
            for (const auto& p : a) amin = std::min(amin, n.dot(p)), amax = std::max(amax, n.dot(p));
            for (const auto& p : b) bmin = std::min(bmin, n.dot(p)), bmax = std::max(bmax, n.dot(p));
            if (amax < bmin || bmax < amin) return true;
        }
    }
    return false;
}
}  // namespace

Eigen::Isometry3d straightFlightFrame(const FlightSpec& f) {
    const int n = f.steps + 1;
    const double level = f.offset_steps * f.rise_m;  // the flight's end nearest to the robot
    Eigen::Isometry3d T = groundFrame(V3::Zero(), f.heading_deg);
    const V2 edge = edgeXY(f);
    if (!f.descending) {
        T.translation() = V3(edge.x(), edge.y(), level);
    } else {
        const V3 top(edge.x(), edge.y(), level);
        T.translation() = top - T.linear() * V3((n - 1) * f.run_m, 0.0, n * f.rise_m);
    }
    return T;
}

Eigen::Vector3d spiralCentre(const FlightSpec& f) {
    const double r = f.distance_m + spiralOuterRadius(f);
    return V3(r * std::cos(f.bearing_deg * kDeg), r * std::sin(f.bearing_deg * kDeg), 0.0);
}

double spiralOuterRadius(const FlightSpec& f) { return f.column_radius_m + f.width_m; }

double spiralStartAngle(const FlightSpec& f) {
    return (f.bearing_deg + 180.0 + f.heading_deg) * kDeg;  // towards the robot, turned
}

double flightFrontX(const FlightSpec& f) {
    const int k = std::abs(f.offset_steps);
    if (f.descending || k == 0) return 0.0;
    return -f.landing_depth_m - (k - 1) * f.run_m;
}

double flightBackX(const FlightSpec& f) {
    const double top = f.steps * f.run_m;  // x of the last nosing
    if (!f.descending) return top + kTopLandingDepthM;
    const int k = std::abs(f.offset_steps);
    return k == 0 ? top : top + f.landing_depth_m + (k - 1) * f.run_m;
}

bool robotClear(const FlightSpec& f) {
    if (f.spiral) return f.distance_m > 0.3;
    const V3 r = straightFlightFrame(f).inverse() * V3::Zero();
    if (f.descending) return r.x() > flightBackX(f) + 0.3;
    if (r.x() < flightFrontX(f) - 0.3) return true;
    return f.offset_steps == 0 && std::abs(r.y()) > 0.5 * f.width_m + 0.6;
}

bool footprintsOverlap(const FlightSpec& a, const FlightSpec& b, double margin_m) {
    return !separated(footprint(a, 0.5 * margin_m), footprint(b, 0.5 * margin_m));
}

}  // namespace stairmap::sim
