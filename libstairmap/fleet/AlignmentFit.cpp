#include "fleet/AlignmentFit.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

namespace stairmap::fleet {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

Eigen::Vector2d unitDirection(const StairEdge& e) {
    const Eigen::Vector2d d = (e.end - e.start).head<2>();
    return d.norm() > 1e-9 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d::UnitX();
}

double directionAngle(const StairEdge& e) {
    const Eigen::Vector2d d = unitDirection(e);
    return std::atan2(d.y(), d.x());
}

/// Length-weighted circular mean of the direction differences first - other.
double initialYaw(const std::vector<EdgeCorrespondence>& pairs) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const auto& p : pairs) {
        const double d = directionAngle(p.first) - directionAngle(p.other);
        const double w = std::max(1e-3, std::min(p.first.length(), p.other.length()));
        sum += w * Eigen::Vector2d(std::cos(d), std::sin(d));
    }
    return std::atan2(sum.y(), sum.x());
}

/// Normal equations of the three residuals of every pair at (tx, ty, yaw); returns chi-square.
double accumulate(const std::vector<EdgeCorrespondence>& pairs, const Eigen::Vector3d& x,
                  const AlignmentParams& prm, Eigen::Matrix3d& H, Eigen::Vector3d& g) {
    H.setZero();
    g.setZero();
    double chi2 = 0.0;
    const double c = std::cos(x.z()), s = std::sin(x.z());
    Eigen::Matrix2d R, dR;
    R << c, -s, s, c;
    dR << -s, -c, c, -s;
    const double w_ang = 1.0 / std::pow(prm.sigma_angle_deg * kDegToRad, 2);
    for (const auto& p : pairs) {
        const Eigen::Vector2d u = unitDirection(p.first), n(-u.y(), u.x());
        const Eigen::Vector2d cb = p.other.centre().head<2>(), ca = p.first.centre().head<2>();
        const Eigen::Vector2d d = R * cb + x.head<2>() - ca, dd = dR * cb;
        const double sigma_lat =
            prm.sigma_lateral_m + 0.5 * std::abs(p.first.length() - p.other.length());
        const double w[2] = {1.0 / (prm.sigma_perp_m * prm.sigma_perp_m),
                             1.0 / (sigma_lat * sigma_lat)};
        const Eigen::Vector2d axes[2] = {n, u};
        for (int k = 0; k < 2; ++k) {
            const Eigen::Vector3d J(axes[k].x(), axes[k].y(), axes[k].dot(dd));
            const double r = axes[k].dot(d);
            H += w[k] * J * J.transpose();
            g += w[k] * J * r;
            chi2 += w[k] * r * r;
        }
        const double r_ang = wrapAngle(x.z() + directionAngle(p.other) - directionAngle(p.first));
        H(2, 2) += w_ang;
        g.z() += w_ang * r_ang;
        chi2 += w_ang * r_ang * r_ang;
    }
    return chi2;
}

}  // namespace

TransformFit fitTransform4(const std::vector<EdgeCorrespondence>& pairs,
                           const AlignmentParams& params) {
    if (pairs.empty()) throw std::invalid_argument("fitTransform4: no nosing pairs");
    Eigen::Vector3d x(0.0, 0.0, initialYaw(pairs));
    {
        const Eigen::Rotation2Dd R(x.z());
        Eigen::Vector2d t = Eigen::Vector2d::Zero();
        for (const auto& p : pairs) t += p.first.centre().head<2>() - R * p.other.centre().head<2>();
        x.head<2>() = t / static_cast<double>(pairs.size());
    }
    Eigen::Matrix3d H;
    Eigen::Vector3d g;
    double chi2 = 0.0;
    for (int iteration = 0; iteration < 8; ++iteration) {
        accumulate(pairs, x, params, H, g);
        const Eigen::Vector3d step = H.ldlt().solve(-g);
        x += step;
        x.z() = wrapAngle(x.z());
        if (step.norm() < 1e-9) break;
    }
    chi2 = accumulate(pairs, x, params, H, g);
    const double n = static_cast<double>(pairs.size());
    const int dof = 3 * static_cast<int>(pairs.size()) - 3;
    const double scale = dof > 0 ? std::max(1.0, chi2 / dof) : 1.0;
    const Eigen::Matrix3d cov = H.inverse() * scale;

    double dz_sum = 0.0, dz_sq = 0.0, perp_sq = 0.0;
    for (const auto& p : pairs) {
        const double dz = p.first.centre().z() - p.other.centre().z();
        dz_sum += dz;
        dz_sq += dz * dz;
    }
    TransformFit fit;
    fit.T_first_other = {x.x(), x.y(), dz_sum / n, x.z()};
    const double var_dz = std::max(dz_sq / n - std::pow(dz_sum / n, 2), 0.0);
    const double prior_z = 0.5 * params.sigma_perp_m;  // a nosing height is measured well
    fit.sigma.z_m = std::sqrt(std::max(var_dz, prior_z * prior_z) / n);
    fit.sigma.xy_m = std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov.topLeftCorner<2, 2>())
                                   .eigenvalues()
                                   .maxCoeff());
    fit.sigma.yaw_deg = std::sqrt(cov(2, 2)) / kDegToRad;
    const Eigen::Rotation2Dd R(x.z());
    for (const auto& p : pairs) {
        const Eigen::Vector2d u = unitDirection(p.first), nrm(-u.y(), u.x());
        const double r = nrm.dot(R * p.other.centre().head<2>() + x.head<2>() - p.first.centre().head<2>());
        perp_sq += r * r;
    }
    fit.rms_perp_m = std::sqrt(perp_sq / n);
    return fit;
}

}  // namespace stairmap::fleet
