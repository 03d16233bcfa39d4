#include "core/LineFusion.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace stairmap {

std::pair<double, double> extentAlong(const LineSegment& s, const Eigen::Vector2d& u) {
    const double a = u.dot(s.start), b = u.dot(s.end);
    return {std::min(a, b), std::max(a, b)};
}

double lineAngle(const LineSegment& a, const LineSegment& b) {
    const double d = std::fmod(std::abs(a.theta - b.theta), M_PI);
    return std::min(d, M_PI - d);
}

LineSegment fuseLines(const LineSegment& a, const LineSegment& b) {
    double rho_b = b.rho, theta_b = b.theta;
    Eigen::Matrix2d cov_b = b.cov;
    if (std::cos(theta_b - a.theta) < 0) {  // opposite normals: use b's other Hessian branch
        rho_b = -rho_b;
        theta_b += M_PI;
        cov_b(0, 1) = -cov_b(0, 1);
        cov_b(1, 0) = -cov_b(1, 0);
    }
    theta_b = a.theta + std::remainder(theta_b - a.theta, 2 * M_PI);
    const Eigen::Matrix2d eps = Eigen::Vector2d(1e-10, 1e-10).asDiagonal();
    const Eigen::Matrix2d ia = (a.cov + eps).inverse(), ib = (cov_b + eps).inverse();
    LineSegment out;
    out.cov = (ia + ib).inverse();
    const Eigen::Vector2d x =
        out.cov * (ia * Eigen::Vector2d(a.rho, a.theta) + ib * Eigen::Vector2d(rho_b, theta_b));
    out.rho = x.x();
    out.theta = x.y();
    if (out.rho < 0) {
        out.rho = -out.rho;
        out.theta += M_PI;
        out.cov(0, 1) = -out.cov(0, 1);
        out.cov(1, 0) = -out.cov(1, 0);
    }
    out.theta = std::remainder(out.theta, 2 * M_PI);
    const Eigen::Vector2d u = out.direction();
    const auto ea = extentAlong(a, u), eb = extentAlong(b, u);
    const Eigen::Vector2d foot = out.rho * Eigen::Vector2d(std::cos(out.theta), std::sin(out.theta));
    out.start = foot + std::min(ea.first, eb.first) * u;
    out.end = foot + std::max(ea.second, eb.second) * u;
    out.num_points = a.num_points + b.num_points;
    out.z = (a.z * a.num_points + b.z * b.num_points) / std::max(1, out.num_points);
    return out;
}

namespace {

/// Common extent of two segments over the shorter one's length.
double overlapFraction(const LineSegment& a, const LineSegment& b) {
    const Eigen::Vector2d u = a.direction();
    const auto ea = extentAlong(a, u), eb = extentAlong(b, u);
    const double common = std::min(ea.second, eb.second) - std::max(ea.first, eb.first);
    return common / std::max(1e-9, std::min(a.length(), b.length()));
}

/// Two detections of mostly the same points (overlapping rows): keep the better supported one,
/// stretched to the union of both extents; fusing would count the shared points twice.
LineSegment keepBetter(const LineSegment& a, const LineSegment& b) {
    LineSegment out = a.num_points >= b.num_points ? a : b;
    const Eigen::Vector2d u = out.direction();
    const auto ea = extentAlong(a, u), eb = extentAlong(b, u);
    const Eigen::Vector2d foot = out.rho * Eigen::Vector2d(std::cos(out.theta), std::sin(out.theta));
    out.start = foot + std::min(ea.first, eb.first) * u;
    out.end = foot + std::max(ea.second, eb.second) * u;
    return out;
}

/// Gap between the XY bounding boxes of two segments (0 when they overlap).
double boxGap(const LineSegment& a, const LineSegment& b) {
    const Eigen::Vector2d a_lo = a.start.cwiseMin(a.end), a_hi = a.start.cwiseMax(a.end);
    const Eigen::Vector2d b_lo = b.start.cwiseMin(b.end), b_hi = b.start.cwiseMax(b.end);
    const Eigen::Vector2d gap = (b_lo - a_hi).cwiseMax(a_lo - b_hi).cwiseMax(0.0);
    return gap.norm();
}

bool sameEdge(const LineSegment& a, const LineSegment& b, const LineFusionParams& p) {
    // Pieces that pass the tests below have a point of the shorter within max_distance across and
    // max_gap along the longer, so boxes farther apart than that never match: a cheap early out.
    if (boxGap(a, b) > p.max_distance_m + p.max_gap_m) return false;
    // Both end points of the shorter line lie near the longer line (short pieces have poorly
    // defined angles, so this replaces an angle test for them), and the extents nearly touch.
    const LineSegment& longer = a.length() >= b.length() ? a : b;
    const LineSegment& shorter = a.length() >= b.length() ? b : a;
    if (std::abs(longer.distanceTo(shorter.start)) > p.max_distance_m ||
        std::abs(longer.distanceTo(shorter.end)) > p.max_distance_m)
        return false;
    if (shorter.length() > 0.5 && lineAngle(a, b) > p.max_angle_deg * M_PI / 180.0) return false;
    const Eigen::Vector2d u = longer.direction();
    const auto ea = extentAlong(a, u), eb = extentAlong(b, u);
    return std::max(ea.first, eb.first) - std::min(ea.second, eb.second) <= p.max_gap_m;
}

}  // namespace

void fuseDuplicateLines(std::vector<LineSegment>& lines, const LineFusionParams& p) {
    std::sort(lines.begin(), lines.end(),
              [](const LineSegment& a, const LineSegment& b) { return a.z < b.z; });
    std::vector<char> alive(lines.size(), 1);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (!alive[i]) continue;
        bool changed = true;
        while (changed) {  // a fused line may now reach a further piece
            changed = false;
            for (std::size_t j = i + 1; j < lines.size() && lines[j].z - lines[i].z <= p.max_dz_m;
                 ++j) {
                if (!alive[j] || !sameEdge(lines[i], lines[j], p)) continue;
                lines[i] = overlapFraction(lines[i], lines[j]) > 0.5 ? keepBetter(lines[i], lines[j])
                                                                     : fuseLines(lines[i], lines[j]);
                alive[j] = 0;
                changed = true;
            }
        }
    }
    std::size_t w = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (alive[i]) lines[w++] = lines[i];
    }
    lines.resize(w);
}

}  // namespace stairmap
