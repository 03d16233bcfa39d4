#include "sim/Trajectory.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace stairmap::sim {

namespace {
constexpr double kDeg = M_PI / 180.0;

double wrapPi(double a) { return std::atan2(std::sin(a), std::cos(a)); }

/// Continuous motion: a list of phases (turn or drive), each with a duration.
struct Phase {
    Eigen::Vector3d from, to;
    double yaw_from, yaw_to;
    double duration_s;
};

std::vector<Phase> buildPhases(const TrajectoryParams& p) {
    std::vector<Phase> phases;
    const auto& w = p.waypoints;
    double yaw = 0.0;
    bool have_yaw = false;
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
        const Eigen::Vector3d d = w[i + 1] - w[i];
        if (d.head<2>().norm() < 1e-9 && std::abs(d.z()) < 1e-9) continue;
        const double heading = d.head<2>().norm() > 1e-9 ? std::atan2(d.y(), d.x()) : yaw;
        if (!have_yaw) {
            yaw = heading;
            have_yaw = true;
        }
        const double turn = wrapPi(heading - yaw);
        if (std::abs(turn) > 1e-9) {
            phases.push_back({w[i], w[i], yaw, yaw + turn,
                              std::abs(turn) / (p.yaw_rate_dps * kDeg)});
        }
        yaw = heading;
        phases.push_back({w[i], w[i + 1], yaw, yaw, d.norm() / p.speed_mps});
    }
    return phases;
}
}  // namespace

Eigen::Isometry3d robotPoseAt(const Eigen::Vector3d& ground, double yaw_rad, double base_height) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = ground + Eigen::Vector3d(0, 0, base_height);
    return T;
}

void validate(const TrajectoryParams& p) {
    auto require = [](bool ok, const std::string& field, const char* what) {
        if (!ok) throw std::invalid_argument(field + ": " + what);
    };
    require(p.waypoints.size() >= 2, "waypoints", "needs at least two waypoints");
    for (const auto& wp : p.waypoints) require(wp.allFinite(), "waypoints", "must be finite");
    require(p.speed_mps > 0 && p.speed_mps < 20, "speed_mps", "must be in (0, 20) m/s");
    require(p.yaw_rate_dps > 0 && p.yaw_rate_dps <= 720, "yaw_rate_dps", "must be in (0, 720]");
    require(p.scan_rate_hz > 0 && p.scan_rate_hz <= 100, "scan_rate_hz", "must be in (0, 100]");
    require(p.base_height_m >= 0 && p.base_height_m < 5, "base_height_m", "must be in [0, 5) m");
}

std::vector<TrajectorySample> sampleTrajectory(const TrajectoryParams& p) {
    validate(p);
    const auto phases = buildPhases(p);
    double total = 0.0;
    for (const auto& ph : phases) total += ph.duration_s;
    std::vector<TrajectorySample> samples;
    const double dt = 1.0 / p.scan_rate_hz;
    std::size_t phase = 0;
    double phase_start = 0.0;
    const auto count = phases.empty() ? 0 : static_cast<std::size_t>(std::floor(total / dt + 1e-9)) + 1;
    for (std::size_t k = 0; k < count; ++k) {
        const double t = k * dt;  // index-based: no accumulated rounding
        while (phase + 1 < phases.size() && t > phase_start + phases[phase].duration_s) {
            phase_start += phases[phase].duration_s;
            ++phase;
        }
        const Phase& ph = phases[phase];
        const double s = ph.duration_s > 0 ? std::min(1.0, (t - phase_start) / ph.duration_s) : 1.0;
        TrajectorySample sample;
        sample.stamp_s = p.start_time_s + t;
        sample.T_world_robot_true = robotPoseAt(ph.from + s * (ph.to - ph.from),
                                                ph.yaw_from + s * (ph.yaw_to - ph.yaw_from),
                                                p.base_height_m);
        sample.T_world_robot_reported = sample.T_world_robot_true;
        samples.push_back(sample);
    }
    return samples;
}

void applySway(std::vector<TrajectorySample>& samples, const SwayParams& sway) {
    if (!(sway.tilt_std_deg >= 0 && sway.tilt_std_deg <= 10))
        throw std::invalid_argument("sway_tilt_deg: must be in [0, 10] deg");
    if (sway.tilt_std_deg == 0) return;
    std::mt19937 rng(sway.seed);
    std::normal_distribution<double> gauss(0.0, sway.tilt_std_deg * kDeg);
    for (auto& s : samples) {
        const double pitch = gauss(rng);
        const double roll = gauss(rng);
        s.T_world_robot_true.linear() = s.T_world_robot_true.linear() *
                                        (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                                         Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                            .toRotationMatrix();
        s.T_world_robot_reported = s.T_world_robot_true;
    }
}

void applyDrift(std::vector<TrajectorySample>& samples, const DriftParams& drift) {
    std::mt19937 rng(drift.seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Identity() * 1e-6;
    for (std::size_t k = 1; k < samples.size(); ++k) {
        const Eigen::Isometry3d step =
            samples[k - 1].T_world_robot_true.inverse() * samples[k].T_world_robot_true;
        const double dist = step.translation().norm();
        const double s_xy = drift.xy_std_per_m * dist;
        const double s_z = drift.z_std_per_m * dist;
        const double s_yaw = drift.yaw_std_deg_per_m * kDeg * dist;
        Eigen::Isometry3d noisy = step;
        noisy.translation() += Eigen::Vector3d(s_xy * gauss(rng), s_xy * gauss(rng), s_z * gauss(rng));
        noisy.linear() = noisy.linear() *
                         Eigen::AngleAxisd(s_yaw * gauss(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix();
        samples[k].T_world_robot_reported = samples[k - 1].T_world_robot_reported * noisy;
        cov(0, 0) += s_xy * s_xy;
        cov(1, 1) += s_xy * s_xy;
        cov(2, 2) += s_z * s_z;
        cov(3, 3) += s_yaw * s_yaw;
        samples[k].covariance = cov;
    }
}

}  // namespace stairmap::sim
