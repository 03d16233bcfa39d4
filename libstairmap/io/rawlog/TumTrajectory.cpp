#include "io/rawlog/TumTrajectory.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace stairmap::io {
namespace {

// Parses one non-comment line into a pose; returns an error text or "".
std::string parseLine(const std::string& line, TimedPose& out) {
    std::istringstream ss(line);
    double v[8];
    std::string token;
    for (int i = 0; i < 8; ++i) {
        char* end = nullptr;
        if (!(ss >> token)) return "expected 8 numbers 't tx ty tz qx qy qz qw'";
        v[i] = std::strtod(token.c_str(), &end);  // strtod also reads nan/inf, rejected below
        if (end != token.c_str() + token.size()) {
            return "expected 8 numbers 't tx ty tz qx qy qz qw', got '" + token + "'";
        }
    }
    if (ss >> token) return "unexpected extra field '" + token + "'";
    for (double x : v) {
        if (!std::isfinite(x)) return "non-finite value";
    }
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);  // Eigen order: w, x, y, z
    if (q.norm() < 1e-9) return "zero quaternion";
    q.normalize();
    out.stamp_s = v[0];
    out.T_world_robot = Eigen::Isometry3d::Identity();
    out.T_world_robot.linear() = q.toRotationMatrix();
    out.T_world_robot.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    return "";
}

bool isBlankOrComment(const std::string& line) {
    const auto pos = line.find_first_not_of(" \t\r");
    return pos == std::string::npos || line[pos] == '#';
}

}  // namespace

TumTrajectory TumTrajectory::read(std::istream& in, const std::string& name) {
    TumTrajectory traj;
    std::string line;
    for (std::size_t line_no = 1; std::getline(in, line); ++line_no) {
        if (isBlankOrComment(line)) continue;
        TimedPose p;
        std::string err = parseLine(line, p);
        if (err.empty() && !traj.poses_.empty() && p.stamp_s <= traj.poses_.back().stamp_s) {
            err = "timestamp not increasing";
        }
        if (!err.empty()) {
            throw std::runtime_error(name + ":" + std::to_string(line_no) + ": " + err);
        }
        traj.poses_.push_back(p);
    }
    if (in.bad()) throw std::runtime_error(name + ": read error");
    return traj;
}

TumTrajectory TumTrajectory::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open TUM trajectory file");
    return read(in, path);
}

void TumTrajectory::write(std::ostream& out) const {
    out << std::setprecision(17);
    for (const TimedPose& p : poses_) {
        const Eigen::Quaterniond q(p.T_world_robot.linear());
        const Eigen::Vector3d& t = p.T_world_robot.translation();
        out << p.stamp_s << ' ' << t.x() << ' ' << t.y() << ' ' << t.z() << ' ' << q.x() << ' '
            << q.y() << ' ' << q.z() << ' ' << q.w() << '\n';
    }
}

void TumTrajectory::save(const std::string& path) const {
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    write(out);
    if (!out) throw std::runtime_error(path + ": write error");
}

void TumTrajectory::append(double stamp_s, const Eigen::Isometry3d& T_world_robot) {
    if (!std::isfinite(stamp_s) || (!poses_.empty() && stamp_s <= poses_.back().stamp_s)) {
        throw std::invalid_argument("TumTrajectory::append: timestamp not increasing");
    }
    poses_.push_back({stamp_s, T_world_robot});
}

std::optional<Eigen::Isometry3d> TumTrajectory::poseAt(double t, double tolerance_s) const {
    if (poses_.empty() || !std::isfinite(t)) return std::nullopt;
    if (t < poses_.front().stamp_s - tolerance_s || t > poses_.back().stamp_s + tolerance_s) {
        return std::nullopt;
    }
    if (t <= poses_.front().stamp_s) return poses_.front().T_world_robot;
    if (t >= poses_.back().stamp_s) return poses_.back().T_world_robot;
    const auto after = std::upper_bound(poses_.begin(), poses_.end(), t,
                                        [](double s, const TimedPose& p) { return s < p.stamp_s; });
    const TimedPose& a = *(after - 1);
    const TimedPose& b = *after;
    const double u = (t - a.stamp_s) / (b.stamp_s - a.stamp_s);
    const Eigen::Quaterniond qa(a.T_world_robot.linear()), qb(b.T_world_robot.linear());
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = qa.slerp(u, qb).normalized().toRotationMatrix();
    T.translation() = (1.0 - u) * a.T_world_robot.translation() + u * b.T_world_robot.translation();
    return T;
}

}  // namespace stairmap::io
