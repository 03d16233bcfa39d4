#include "io/follow/GrowingTum.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace stairmap::io {

namespace fs = std::filesystem;

GrowingTum::GrowingTum(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    if (!fs::is_regular_file(path_, ec)) {
        throw std::runtime_error(path_ + (fs::exists(path_, ec) ? ": not a file" : ": no such file"));
    }
}

bool GrowingTum::refresh() {
    std::error_code ec;
    const std::uint64_t size = fs::file_size(path_, ec);
    if (ec) throw std::runtime_error(path_ + ": cannot read the pose file any more (" + ec.message() + ")");
    if (size < offset_) throw std::runtime_error(path_ + ": the pose file shrank (rewritten rather than appended to)");
    if (size == offset_) return false;
    std::ifstream in(path_, std::ios::binary);
    std::string chunk(size - offset_, '\0');
    if (!in.seekg(std::streamoff(offset_)) || !in.read(chunk.data(), std::streamsize(chunk.size()))) {
        throw std::runtime_error(path_ + ": cannot read the pose file");
    }
    const std::size_t before = trajectory_.size();
    std::size_t start = 0;
    for (std::size_t nl = chunk.find('\n'); nl != std::string::npos; nl = chunk.find('\n', start)) {
        ++line_number_;
        parseLine(chunk.substr(start, nl - start));
        start = nl + 1;
    }
    offset_ += start;  // a partial last line stays for the next refresh
    return trajectory_.size() > before;
}

void GrowingTum::forgetBefore(double t) {
    const auto& poses = trajectory_.poses();
    std::size_t first = 0;  // the last pose at or before t stays
    while (first + 1 < poses.size() && poses[first + 1].stamp_s <= t) ++first;
    if (first == 0 || 2 * first < poses.size()) return;
    TumTrajectory kept;
    for (std::size_t i = first; i < poses.size(); ++i) kept.append(poses[i].stamp_s, poses[i].T_world_robot);
    trajectory_ = std::move(kept);
}

void GrowingTum::parseLine(const std::string& line) {
    const std::string where = path_ + ":" + std::to_string(line_number_) + ": ";
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') return;
    std::istringstream in(line);
    double v[8];
    for (double& x : v) {
        if (!(in >> x)) throw std::runtime_error(where + "expected 8 numbers 't x y z qx qy qz qw'");
        if (!std::isfinite(x)) throw std::runtime_error(where + "non-finite value");
    }
    std::string extra;
    if (in >> extra) throw std::runtime_error(where + "more than 8 values");
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    if (!(q.norm() > 1e-9)) throw std::runtime_error(where + "zero quaternion");
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = q.normalized().toRotationMatrix();
    T.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    try {
        trajectory_.append(v[0], T);
        ++poses_read_;
    } catch (const std::exception&) {
        throw std::runtime_error(where + "time " + std::to_string(v[0]) + " does not increase");
    }
}

}  // namespace stairmap::io
