#include "core/StairEdgeFusion.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

/// A line n(theta) . (p - origin) = rho with covariance P of (rho, theta).
struct LocalLine {
    double rho = 0.0;
    double theta = 0.0;
    Eigen::Matrix2d P = Eigen::Matrix2d::Identity();
};

Eigen::Vector2d normalOf(double theta) { return {std::cos(theta), std::sin(theta)}; }
Eigen::Vector2d tangentOf(double theta) { return {-std::sin(theta), std::cos(theta)}; }

/// Length of the overlap of b's extent with a's, both projected on a's XY direction (negative:
/// the gap between them).
double overlapAlong(const StairEdge& a, const StairEdge& b) {
    const Eigen::Vector2d d = (a.end - a.start).head<2>();
    const double len = d.norm();
    if (len < 1e-9) return 0.0;
    const Eigen::Vector2d u = d / len;
    const double s1 = (b.start - a.start).head<2>().dot(u);
    const double s2 = (b.end - a.start).head<2>().dot(u);
    return std::min(len, std::max(s1, s2)) - std::max(0.0, std::min(s1, s2));
}

/// Origin-independent uncertainty of an edge: (perpendicular variance at the centre, var theta).
Eigen::Vector2d intrinsicVariances(const StairEdge& e, const MergeParams& params) {
    const double min_perp = params.min_sigma_m * params.min_sigma_m;
    const double min_theta = std::pow(params.min_sigma_deg * kDegToRad, 2);
    const Eigen::Matrix2d& C = e.cov_rho_theta;
    double var_theta = C(1, 1);
    double var_perp = C(0, 0);
    // The Schur complement var(rho | theta) does not depend on where rho is measured from.
    if (var_theta > 0.0 && std::isfinite(var_theta)) var_perp = C(0, 0) - C(0, 1) * C(1, 0) / var_theta;
    if (!(var_perp > min_perp)) var_perp = min_perp;
    if (!(var_theta > min_theta)) var_theta = min_theta;
    return {var_perp, var_theta};
}

LocalLine toLocalLine(const StairEdge& e, const Eigen::Vector2d& origin, double heading_rad,
                      const MergeParams& params) {
    const Eigen::Vector2d d = (e.end - e.start).head<2>();
    Eigen::Vector2d n(-d.y(), d.x());
    if (n.dot(normalOf(heading_rad)) < 0.0) n = -n;
    LocalLine line;
    // theta within pi of the heading, so that the two lines average sensibly.
    line.theta = heading_rad + std::remainder(std::atan2(n.y(), n.x()) - heading_rad, 2 * M_PI);
    const Eigen::Vector2d c = e.centre().head<2>() - origin;
    line.rho = c.dot(normalOf(line.theta));
    const Eigen::Vector2d var = intrinsicVariances(e, params);
    Eigen::Matrix2d J;  // (rho_centre, theta) -> (rho_origin, theta)
    J << 1.0, c.dot(tangentOf(line.theta)), 0.0, 1.0;
    line.P = J * var.asDiagonal() * J.transpose();
    return line;
}

double weightedEnd(double ea, double eb, int wa, int wb, double tol, bool lower) {
    if (std::abs(ea - eb) <= tol) return (wa * ea + wb * eb) / static_cast<double>(wa + wb);
    return lower ? std::min(ea, eb) : std::max(ea, eb);
}

/// Covariance about `origin` -> about the frame origin, in the rho >= 0 convention of
/// core/Staircase.h (flipping the normal negates rho and the cross term only).
Eigen::Matrix2d covarianceAboutFrameOrigin(const Eigen::Matrix2d& P, const Eigen::Vector2d& origin,
                                           const Eigen::Vector2d& foot, double theta) {
    Eigen::Matrix2d J;
    J << 1.0, origin.dot(tangentOf(theta)), 0.0, 1.0;
    Eigen::Matrix2d C = J * P * J.transpose();
    if (foot.dot(normalOf(theta)) < 0.0) {
        C(0, 1) = -C(0, 1);
        C(1, 0) = -C(1, 0);
    }
    return C;
}

}  // namespace

bool isSameStairEdge(const StairEdge& a, const StairEdge& b, const MergeParams& params) {
    if (std::abs(a.centre().z() - b.centre().z()) > params.max_height_diff_m) return false;
    if (edgeSpacingXY(a, b) > params.max_distance_m) return false;
    double dalpha = std::abs(a.orientationRad() - b.orientationRad());
    dalpha = std::min(dalpha, M_PI - dalpha);
    if (dalpha > params.max_angle_deg * kDegToRad) return false;
    const double needed =
        std::min(params.min_edge_overlap_m, 0.5 * std::min(a.length(), b.length()));
    return overlapAlong(a, b) >= needed;
}

StairEdge fuseEdges(const StairEdge& a, int weight_a, const StairEdge& b, int weight_b,
                    double heading_rad, const MergeParams& params) {
    weight_a = std::max(1, weight_a);
    weight_b = std::max(1, weight_b);
    const Eigen::Vector2d origin = a.centre().head<2>();
    const LocalLine la = toLocalLine(a, origin, heading_rad, params);
    const LocalLine lb = toLocalLine(b, origin, heading_rad, params);
    const Eigen::Matrix2d Ia = la.P.inverse(), Ib = lb.P.inverse();
    const Eigen::Matrix2d P = (Ia + Ib).inverse();
    const Eigen::Vector2d x = P * (Ia * Eigen::Vector2d(la.rho, la.theta) +
                                   Ib * Eigen::Vector2d(lb.rho, lb.theta));
    const Eigen::Vector2d n = normalOf(x(1)), t = tangentOf(x(1));
    const Eigen::Vector2d foot = origin + x(0) * n;
    // Extents along the fused line (t points left when facing the heading).
    auto extent = [&](const StairEdge& e) {
        const double s1 = (e.start.head<2>() - foot).dot(t), s2 = (e.end.head<2>() - foot).dot(t);
        return std::make_pair(std::min(s1, s2), std::max(s1, s2));
    };
    const auto [a_lo, a_hi] = extent(a);
    const auto [b_lo, b_hi] = extent(b);
    const double tol = params.endpoint_tolerance_m;
    const double lo = weightedEnd(a_lo, b_lo, weight_a, weight_b, tol, true);
    const double hi = weightedEnd(a_hi, b_hi, weight_a, weight_b, tol, false);
    const double wza = 1.0 / intrinsicVariances(a, params)(0);
    const double wzb = 1.0 / intrinsicVariances(b, params)(0);
    const double z = (wza * a.centre().z() + wzb * b.centre().z()) / (wza + wzb);

    StairEdge fused;
    fused.start << foot + hi * t, z;  // start on the left when facing the heading
    fused.end << foot + lo * t, z;
    fused.num_points = a.num_points + b.num_points;
    fused.cov_rho_theta = covarianceAboutFrameOrigin(P, origin, foot, x(1));
    return fused;
}

}  // namespace stairmap
