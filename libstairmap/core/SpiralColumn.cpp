#include "core/SpiralColumn.h"

#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace stairmap {
namespace {

/// Kasa fit of x^2 + y^2 + D x + E y + F = 0 to `pts` (relative to the axis): centre and radius.
bool fitCircle(const std::vector<Eigen::Vector2d>& pts, Eigen::Vector2d& centre, double& radius) {
    if (pts.size() < 3) return false;
    Eigen::MatrixXd a(static_cast<Eigen::Index>(pts.size()), 3);
    Eigen::VectorXd b(static_cast<Eigen::Index>(pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto row = static_cast<Eigen::Index>(i);
        a(row, 0) = pts[i].x();
        a(row, 1) = pts[i].y();
        a(row, 2) = 1.0;
        b(row) = -pts[i].squaredNorm();
    }
    const Eigen::Vector3d x = a.colPivHouseholderQr().solve(b);
    centre = Eigen::Vector2d(-0.5 * x(0), -0.5 * x(1));
    const double r2 = centre.squaredNorm() - x(2);
    if (!std::isfinite(r2) || !(r2 > 0.0)) return false;
    radius = std::sqrt(r2);
    return true;
}

}  // namespace

std::optional<SpiralColumn> fitSpiralColumn(const PointCloud& cloud, const Eigen::Vector2d& axis,
                                            double z_lo, double z_hi, double reach,
                                            const SpiralColumnParams& p) {
    if (p.sectors < 3 || !(reach > 0.0)) return std::nullopt;
    std::vector<double> nearest(static_cast<std::size_t>(p.sectors), reach);
    std::vector<Eigen::Vector2d> at(static_cast<std::size_t>(p.sectors));
    for (const Eigen::Vector3f& q : cloud) {
        if (!(q.z() > z_lo && q.z() < z_hi)) continue;  // also drops NaN
        const Eigen::Vector2d d(q.x() - axis.x(), q.y() - axis.y());
        const double r = d.norm();
        if (!(r < reach)) continue;
        const double t = (std::atan2(d.y(), d.x()) + M_PI) / (2.0 * M_PI);
        const auto k = static_cast<std::size_t>(
            std::min(p.sectors - 1, std::max(0, static_cast<int>(t * p.sectors))));
        if (r >= nearest[k]) continue;  // starts at reach: a sector below it has been seen
        nearest[k] = r;
        at[k] = d;
    }
    std::vector<Eigen::Vector2d> pts;
    for (std::size_t k = 0; k < nearest.size(); ++k)
        if (nearest[k] < reach) pts.push_back(at[k]);
    if (static_cast<int>(pts.size()) < p.min_sectors) return std::nullopt;
    Eigen::Vector2d centre;
    double radius = 0.0;
    if (!fitCircle(pts, centre, radius)) return std::nullopt;
    for (int it = 0; it < p.refits; ++it) {
        std::vector<Eigen::Vector2d> in;
        for (const Eigen::Vector2d& q : pts)
            if (std::abs((q - centre).norm() - radius) <= p.inlier_m) in.push_back(q);
        if (static_cast<int>(in.size()) < p.min_sectors / 2 || !fitCircle(in, centre, radius))
            break;
        pts.swap(in);
    }
    if (centre.norm() > p.max_centre_shift_m || radius < p.min_radius_m) return std::nullopt;
    return SpiralColumn{axis + centre, radius};
}

}  // namespace stairmap
