#include "core/StaircaseMerge.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

/// Interval of an edge projected on direction u (unit, XY).
std::pair<double, double> extentAlong(const StairEdge& e, const Eigen::Vector2d& u) {
    const double s0 = u.dot(e.start.head<2>());
    const double s1 = u.dot(e.end.head<2>());
    return {std::min(s0, s1), std::max(s0, s1)};
}

double axialAngleDiff(double a, double b) {
    double d = std::fmod(std::abs(a - b), M_PI);
    return std::min(d, M_PI - d);
}

Eigen::Matrix2d regularised(const Eigen::Matrix2d& cov) {
    // Guard against singular covariances (10 um / 6e-4 deg floor).
    return cov + Eigen::Vector2d(1e-10, 1e-10).asDiagonal().toDenseMatrix();
}

/// Number of matching pairs when a[k] is aligned with b[k + offset].
int countMatches(const Staircase& a, const Staircase& b, int offset, const MergeParams& p) {
    int matches = 0;
    for (int k = 0; k < static_cast<int>(a.steps.size()); ++k) {
        const int j = k + offset;
        if (j < 0 || j >= static_cast<int>(b.steps.size())) continue;
        if (isSameStairEdge(a.steps[k], b.steps[j], p)) ++matches;
    }
    return matches;
}

/// Algorithm 2, lines 2-9, generalised: the offset j - i with the most matching pairs.
std::optional<int> bestOffset(const Staircase& a, const Staircase& b, const MergeParams& p) {
    std::optional<int> best;
    int best_count = 0;
    const int na = static_cast<int>(a.steps.size());
    const int nb = static_cast<int>(b.steps.size());
    for (int offset = -(na - 1); offset <= nb - 1; ++offset) {
        const int c = countMatches(a, b, offset, p);
        if (c > best_count) {
            best_count = c;
            best = offset;
        }
    }
    return best;
}

}  // namespace

bool isSameStairEdge(const StairEdge& a, const StairEdge& b, const MergeParams& p) {
    if (std::abs(a.centre().z() - b.centre().z()) > p.max_height_diff_m) return false;
    if (edgeSpacingXY(a, b) > p.max_distance_m) return false;
    if (axialAngleDiff(a.orientationRad(), b.orientationRad()) > p.max_angle_deg * M_PI / 180.0)
        return false;
    const Eigen::Vector2d u = (a.end - a.start).head<2>().normalized();
    const auto ea = extentAlong(a, u);
    const auto eb = extentAlong(b, u);
    const double gap = std::max(ea.first, eb.first) - std::min(ea.second, eb.second);
    return gap <= p.max_lateral_gap_m;
}

StairEdge fuseEdges(const StairEdge& a, const StairEdge& b) {
    const Eigen::Vector2d la = a.rhoTheta();
    Eigen::Vector2d lb = b.rhoTheta();
    Eigen::Matrix2d cb = b.cov_rho_theta;
    // Express b in the same branch as a: flip the normal if it points the other way.
    if (std::cos(lb.y() - la.y()) < 0) {
        lb = Eigen::Vector2d(-lb.x(), lb.y() + M_PI);
        cb(0, 1) = -cb(0, 1);
        cb(1, 0) = -cb(1, 0);
    }
    lb.y() = la.y() + std::remainder(lb.y() - la.y(), 2 * M_PI);
    const Eigen::Matrix2d ia = regularised(a.cov_rho_theta).inverse();
    const Eigen::Matrix2d ib = regularised(cb).inverse();
    const Eigen::Matrix2d cov = (ia + ib).inverse();
    const Eigen::Vector2d line = cov * (ia * la + ib * lb);

    const Eigen::Vector2d n(std::cos(line.y()), std::sin(line.y()));
    Eigen::Vector2d u(-n.y(), n.x());
    if (u.dot((a.end - a.start).head<2>()) < 0) u = -u;
    const auto ea = extentAlong(a, u);
    const auto eb = extentAlong(b, u);
    const double s0 = std::min(ea.first, eb.first);
    const double s1 = std::max(ea.second, eb.second);
    const double wa = std::max(a.num_points, 1);
    const double wb = std::max(b.num_points, 1);
    const double z = (wa * a.centre().z() + wb * b.centre().z()) / (wa + wb);

    StairEdge out;
    const Eigen::Vector2d p0 = line.x() * n;
    out.start << p0 + s0 * u, z;
    out.end << p0 + s1 * u, z;
    out.cov_rho_theta = cov;
    out.num_points = a.num_points + b.num_points;
    return out;
}

std::optional<Staircase> mergeStaircases(const Staircase& a, const Staircase& b,
                                         const MergeParams& p) {
    if (a.direction != b.direction) {
        throw std::invalid_argument(
            "mergeStaircases: directions differ; convert both with toBottomUp() first");
    }
    const auto offset = bestOffset(a, b, p);
    if (!offset) return std::nullopt;  // NO_MATCH
    const int o = *offset;             // a[k] <-> b[k + o]
    const int na = static_cast<int>(a.steps.size());
    const int nb = static_cast<int>(b.steps.size());
    const int shift_a = std::max(0, o);   // position of a[k] in the merged list
    const int shift_b = std::max(0, -o);  // position of b[j]
    const int n = std::max(na + shift_a, nb + shift_b);

    Staircase out = a;
    out.steps.clear();
    for (int pos = 0; pos < n; ++pos) {
        const int k = pos - shift_a;
        const int j = pos - shift_b;
        const bool has_a = k >= 0 && k < na;
        const bool has_b = j >= 0 && j < nb;
        if (has_a && has_b) {
            const StairEdge& ea = a.steps[k];
            const StairEdge& eb = b.steps[j];
            if (isSameStairEdge(ea, eb, p)) out.steps.push_back(fuseEdges(ea, eb));
            else out.steps.push_back(ea.num_points >= eb.num_points ? ea : eb);  // conflict
        } else if (has_a) {
            out.steps.push_back(a.steps[k]);
        } else if (has_b) {
            out.steps.push_back(b.steps[j]);
        }
    }
    estimateGeometry(out);
    return out;
}

Staircase toBottomUp(const Staircase& stairs) {
    Staircase out = stairs;
    if (stairs.direction == StairDirection::Descending) {
        std::reverse(out.steps.begin(), out.steps.end());
        for (auto& e : out.steps) std::swap(e.start, e.end);  // keep start on the left of heading
        out.direction = StairDirection::Ascending;
        out.heading_rad = std::remainder(stairs.heading_rad + M_PI, 2 * M_PI);
    }
    estimateGeometry(out);
    return out;
}

}  // namespace stairmap
