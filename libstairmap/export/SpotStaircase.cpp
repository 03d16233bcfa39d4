#include "export/SpotStaircase.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "export/FlightGeometry.h"

namespace stairmap::exporting {
namespace {

/// World -> stairs frame for a frame at `origin` rotated by `yaw` about Z.
Eigen::Vector3d toStairs(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, double yaw) {
    const Eigen::Vector3d d = p - origin;
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()};
}

/// Indices [begin, end) of the runs of steps between landings.
std::vector<std::pair<std::size_t, std::size_t>> stepRuns(const Staircase& s, double factor) {
    const Eigen::Vector2d up = headingVector(s.heading_rad);
    std::vector<double> gaps;
    for (std::size_t i = 0; i + 1 < s.steps.size(); ++i) {
        gaps.push_back((s.steps[i + 1].centre() - s.steps[i].centre()).head<2>().dot(up));
    }
    std::vector<double> sorted = gaps;
    std::sort(sorted.begin(), sorted.end());
    const double limit = sorted.empty() ? 0.0 : factor * sorted[sorted.size() / 2];
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    std::size_t begin = 0;
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        if (gaps.size() >= 2 && gaps[i] > limit) {
            runs.emplace_back(begin, i + 1);
            begin = i + 1;
        }
    }
    runs.emplace_back(begin, s.steps.size());
    return runs;
}

SpotStaircase spotRun(const StaircaseLandmark& lm, std::size_t begin, std::size_t end,
                      const SpotParams& params, const SpotLanding* shared_bottom) {
    const Staircase& s = lm.stairs;
    SpotStaircase out;
    out.yaw_rad = s.heading_rad;
    out.origin_world = s.steps[begin].centre() - Eigen::Vector3d(0.0, 0.0, s.step_height);
    out.average_rise_m = s.step_height;
    out.average_run_m = s.step_depth;
    double width_sum = 0.0;
    for (std::size_t i = begin; i < end; ++i) {
        const StairEdge& e = s.steps[i];
        SpotStep step;
        step.point = toStairs(e.centre(), out.origin_world, out.yaw_rad);
        // Edges run left to right facing uphill: north is the edge direction turned left.
        const Eigen::Vector3d a = toStairs(e.start, out.origin_world, out.yaw_rad);
        const Eigen::Vector3d b = toStairs(e.end, out.origin_world, out.yaw_rad);
        const Eigen::Vector2d along = (b - a).head<2>();
        step.north = along.norm() > 0 ? Eigen::Vector2d(-along.y(), along.x()).normalized()
                                      : Eigen::Vector2d::UnitX();
        step.width_m = e.length();
        width_sum += step.width_m;
        out.steps.push_back(step);
    }
    out.average_width_m = width_sum / static_cast<double>(end - begin);
    const double half = 0.5 * params.landing_length_m;
    if (shared_bottom) {
        out.bottom_landing = *shared_bottom;
        out.bottom_landing.centre = Eigen::Vector3d(-shared_bottom->extent_x_m, 0.0, 0.0);
    } else {
        out.bottom_landing = {Eigen::Vector3d(-half, 0.0, 0.0), half, 0.5 * out.average_width_m};
    }
    const Eigen::Vector3d top = out.steps.back().point;
    out.top_landing = {Eigen::Vector3d(top.x() + half, 0.0, top.z()), half,
                       0.5 * out.average_width_m};
    return out;
}

}  // namespace

std::vector<SpotStaircase> toSpotStaircases(const StaircaseLandmark& lm, const SpotParams& params) {
    std::vector<SpotStaircase> out;
    if (lm.stairs.steps.empty()) return out;
    const auto runs = stepRuns(lm.stairs, params.landing_run_factor);
    for (std::size_t r = 0; r < runs.size(); ++r) {
        std::optional<SpotLanding> mid;
        if (r > 0) {
            // The landing between the previous run's top nosing and this run's first riser.
            const Eigen::Vector2d up = headingVector(lm.stairs.heading_rad);
            const double gap = (lm.stairs.steps[runs[r].first].centre() -
                                lm.stairs.steps[runs[r].first - 1].centre())
                                   .head<2>()
                                   .dot(up);
            mid = SpotLanding{Eigen::Vector3d::Zero(), 0.5 * gap, 0.5 * lm.stairs.step_width};
        }
        SpotStaircase st =
            spotRun(lm, runs[r].first, runs[r].second, params, mid ? &*mid : nullptr);
        st.id = "stairmap-" + std::to_string(lm.id) + "-" + std::to_string(r);
        st.confirmed = lm.confirmed;
        if (r + 1 < runs.size()) {
            // The top landing is the mid-flight landing that follows.
            const Eigen::Vector2d up = headingVector(lm.stairs.heading_rad);
            const std::size_t next = runs[r + 1].first;
            const double gap = (lm.stairs.steps[next].centre() - lm.stairs.steps[next - 1].centre())
                                   .head<2>()
                                   .dot(up);
            st.top_landing.extent_x_m = 0.5 * gap;
            st.top_landing.centre.x() = st.steps.back().point.x() + 0.5 * gap;
        }
        out.push_back(std::move(st));
    }
    return out;
}

}  // namespace stairmap::exporting
