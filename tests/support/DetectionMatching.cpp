#include "support/DetectionMatching.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace stairmap::test {
namespace {

double pointToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (a + t * d - p).norm();
}

double pointToLineXY(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector2d d = (b - a).head<2>().normalized();
    const Eigen::Vector2d v = (p - a).head<2>();
    return std::abs(d.x() * v.y() - d.y() * v.x());
}

}  // namespace

const Staircase* matchTruth(const DetectionResult& result, const StairTruth& truth) {
    const auto& [a, b] = truth.nosings.front();
    for (const auto& s : result.staircases) {
        if ((s.direction == StairDirection::Ascending) != truth.ascending || s.steps.empty()) continue;
        const Eigen::Vector3d c = s.steps.front().centre();
        if (pointToLineXY(c, a, b) < 0.08 && std::abs(c.z() - a.z()) < 0.05) return &s;
    }
    return nullptr;
}

double nosingError(const Staircase& s, const StairTruth& truth) {
    double worst = 0.0;
    for (const auto& e : s.steps) {
        double best = std::numeric_limits<double>::infinity();
        for (const auto& [a, b] : truth.nosings) best = std::min(best, pointToSegment(e.centre(), a, b));
        worst = std::max(worst, best);
    }
    return worst;
}

double headingError(const Staircase& s, const StairTruth& truth) {
    return std::abs(std::remainder(s.heading_rad - truth.heading_rad, 2 * M_PI));
}

std::string describe(const DetectionResult& result) {
    std::ostringstream o;
    o << "floor_z=" << result.floor_z << " staircases=" << result.staircases.size();
    for (const auto& s : result.staircases) {
        o << "\n  " << (s.direction == StairDirection::Ascending ? "asc" : "desc")
          << " steps=" << s.steps.size() << " h=" << s.step_height << " d=" << s.step_depth
          << " w=" << s.step_width << " heading_deg=" << s.heading_rad * 180 / M_PI << " loc=("
          << s.location.transpose() << ")";
    }
    return o.str();
}

}  // namespace stairmap::test
