#include "core/LineFit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace stairmap {

LineSegment fitLine(const RowPointView& pts, std::size_t first, std::size_t last, double sigma) {
    const std::size_t n = last - first + 1;
    double cx = 0, cy = 0, cz = 0;
    for (std::size_t i = first; i <= last; ++i) {
        cx += pts.x[i];
        cy += pts.y[i];
        cz += pts.z[i];
    }
    cx /= n;
    cy /= n;
    cz /= n;
    double sxx = 0, syy = 0, sxy = 0;
    for (std::size_t i = first; i <= last; ++i) {
        const double dx = pts.x[i] - cx, dy = pts.y[i] - cy;
        sxx += dx * dx;
        syy += dy * dy;
        sxy += dx * dy;
    }
    // Normal angle of the TLS line: minimises sum (n . (p - c))^2.
    double theta = 0.5 * std::atan2(-2.0 * sxy, syy - sxx);
    Eigen::Vector2d nrm(std::cos(theta), std::sin(theta));
    double rho = nrm.x() * cx + nrm.y() * cy;
    if (rho < 0) {
        rho = -rho;
        theta += M_PI;
        nrm = -nrm;
    }
    if (theta > M_PI) theta -= 2 * M_PI;  // 0.5 * atan2 is in (-pi/2, pi/2]: now in (-pi, pi]
    const Eigen::Vector2d u(-nrm.y(), nrm.x());
    const double s_tt = u.x() * u.x() * sxx + 2 * u.x() * u.y() * sxy + u.y() * u.y() * syy;
    const double s_nn = std::max(0.0, sxx + syy - s_tt);
    const double resid2 = n > 2 ? s_nn / (n - 2) : 0.0;
    const double s2 = std::max(sigma * sigma, resid2);

    LineSegment seg;
    seg.rho = rho;
    seg.theta = theta;
    seg.z = cz;
    seg.num_points = static_cast<int>(n);
    const double var_rho_c = s2 / n;
    const double var_theta = s2 / std::max(s_tt, 1e-12);
    const double drho_dtheta = -cx * nrm.y() + cy * nrm.x();  // d(rho)/d(theta) at the centroid
    seg.cov << var_rho_c + drho_dtheta * drho_dtheta * var_theta, drho_dtheta * var_theta,
        drho_dtheta * var_theta, var_theta;
    // End points: projections of the first and last point onto the line.
    const Eigen::Vector2d foot = rho * nrm;
    const Eigen::Vector2d p0(pts.x[first], pts.y[first]);
    const Eigen::Vector2d p1(pts.x[last], pts.y[last]);
    seg.start = foot + u * u.dot(p0);
    seg.end = foot + u * u.dot(p1);
    return seg;
}

double lineMahalanobis2(const LineSegment& a, const LineSegment& b) {
    Eigen::Vector2d d(a.rho - b.rho, std::remainder(a.theta - b.theta, 2 * M_PI));
    const Eigen::Matrix2d c = a.cov + b.cov;
    const double det = c.determinant();
    if (!(det > 0)) return 1e300;
    return d.dot(c.inverse() * d);
}

}  // namespace stairmap
