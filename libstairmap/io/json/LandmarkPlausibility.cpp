#include "io/json/LandmarkPlausibility.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace stairmap::io {
namespace {

std::string show(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

[[noreturn]] void fail(const std::string& path, double value, const std::string& problem) {
    throw std::runtime_error(path + ": " + show(value) + " " + problem);
}

void requireIn(double v, double lo, double hi, const std::string& path) {
    if (!(v >= lo && v <= hi)) fail(path, v, "is outside [" + show(lo) + ", " + show(hi) + "]");
}

}  // namespace

void checkWorldZ(double z, const std::string& path) {
    if (!(std::abs(z) <= kWorldBoundZM))
        fail(path, z, "is outside the world bound |z| <= " + show(kWorldBoundZM) + " m");
}

namespace {

void requirePoint(const Eigen::Vector3d& p, const std::string& path) {
    for (int k = 0; k < 2; ++k) {
        if (!(std::abs(p[k]) <= kWorldBoundXyM))
            fail(path + "[" + std::to_string(k) + "]", p[k],
                 "is outside the world bound |x|, |y| <= " + show(kWorldBoundXyM) + " m");
    }
    checkWorldZ(p.z(), path + "[2]");
}

void checkStep(const StairEdge& e, int observations, const std::string& path) {
    requirePoint(e.start, path + ".start");
    requirePoint(e.end, path + ".end");
    requireIn(e.num_points, 0, kMaxCount, path + ".num_points");
    requireIn(observations, 1, kMaxCount, path + ".observations");
    for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < 2; ++c) {
            const std::string where = path + ".cov_rho_theta[" + std::to_string(r) + "][" + std::to_string(c) + "]";
            // Variances (diagonal) are never negative; no entry of a physical edge comes near the bound.
            requireIn(e.cov_rho_theta(r, c), r == c ? 0.0 : -kMaxVariance, kMaxVariance, where);
        }
    }
}

void checkStaircase(const StaircaseLandmark& lm, const std::string& path) {
    requireIn(lm.id, 0, kMaxCount, path + ".id");
    requireIn(lm.observations, 1, kMaxCount, path + ".observations");
    requireIn(lm.first_seen_s, -kMaxStampS, kMaxStampS, path + ".first_seen_s");
    requireIn(lm.last_seen_s, lm.first_seen_s, kMaxStampS, path + ".last_seen_s");
    requireIn(lm.bottom_floor, -1, kMaxCount, path + ".bottom_floor");
    requireIn(lm.top_floor, -1, kMaxCount, path + ".top_floor");
    const Staircase& s = lm.stairs;
    requireIn(s.step_height, 0.0, kMaxStepHeightM, path + ".step_height");
    requireIn(s.step_depth, 0.0, kMaxStepDepthM, path + ".step_depth");
    requireIn(s.step_width, 0.0, kMaxStepWidthM, path + ".step_width");
    requireIn(s.slope_rad, 0.0, M_PI / 2, path + ".slope_rad");
    requireIn(s.heading_rad, -2 * M_PI, 2 * M_PI, path + ".heading_rad");
    requirePoint(s.location, path + ".location");
    requireIn(static_cast<double>(s.steps.size()), 1, kMaxStepsPerStaircase, path + ".num_steps");
    for (std::size_t k = 0; k < s.steps.size(); ++k) {
        checkStep(s.steps[k], lm.step_observations.at(k), path + ".steps[" + std::to_string(k) + "]");
    }
}

void checkFloor(const Floor& f, const std::string& path) {
    requireIn(f.id, 0, kMaxCount, path + ".id");
    checkWorldZ(f.z, path + ".z");
    requireIn(f.robot_samples, 0, kMaxCount, path + ".robot_samples");
    requireIn(f.staircase_ends, 0, kMaxCount, path + ".staircase_ends");
    // Sums of heights within the world bound.
    const double robot_bound = kWorldBoundZM * f.robot_samples, end_bound = kWorldBoundZM * f.staircase_ends;
    requireIn(f.robot_z_sum, -robot_bound, robot_bound, path + ".robot_z_sum");
    requireIn(f.end_z_sum, -end_bound, end_bound, path + ".end_z_sum");
}

void checkContinuation(const LandmarkMapState& state) {
    const std::string c = "continuation";
    requireIn(state.next_landmark_id, 0, kMaxCount, c + ".next_landmark_id");
    requireIn(state.next_floor_id, 0, kMaxCount, c + ".next_floor_id");
    for (std::size_t i = 0; i < state.floor_levels.size(); ++i)
        checkFloor(state.floor_levels[i], c + ".floor_levels[" + std::to_string(i) + "]");
    std::size_t i = 0;
    for (const auto& [id, into] : state.absorbed) {
        const std::string path = c + ".absorbed[" + std::to_string(i++) + "]";
        requireIn(id, 0, kMaxCount, path + ".id");
        requireIn(into, 0, kMaxCount, path + ".into");
    }
    for (std::size_t t = 0; t < state.transits.size(); ++t) {
        const std::string path = c + ".transits[" + std::to_string(t) + "]";
        requireIn(state.transits[t].stamp_s, -kMaxStampS, kMaxStampS, path + ".stamp_s");
        const auto& points = state.transits[t].floor_path;
        for (std::size_t k = 0; k < points.size(); ++k)
            requirePoint(points[k], path + ".floor_path[" + std::to_string(k) + "]");
    }
}

}  // namespace

void checkLandmarkPlausibility(const LandmarkMapState& state) {
    for (std::size_t i = 0; i < state.staircases.size(); ++i)
        checkStaircase(state.staircases[i], "staircases[" + std::to_string(i) + "]");
    checkContinuation(state);
}

}  // namespace stairmap::io
