#include "export/FlightGeometry.h"

#include <algorithm>
#include <cmath>

#include "core/UpperMedian.h"

namespace stairmap::exporting {
namespace {

double sampleStd(const std::vector<double>& v) {
    if (v.size() < 2) return 0.0;
    double mean = 0.0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    double ss = 0.0;
    for (double x : v) ss += (x - mean) * (x - mean);
    return std::sqrt(ss / static_cast<double>(v.size() - 1));
}

/// Horizontal spacing of consecutive nosings along the uphill heading.
std::vector<double> spacings(const std::vector<StairEdge>& steps, const Eigen::Vector2d& up) {
    std::vector<double> out;
    for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
        out.push_back((steps[i + 1].centre() - steps[i].centre()).head<2>().dot(up));
    }
    return out;
}

Landing landingBetween(const StairEdge& lower, const StairEdge& upper, double spacing) {
    Landing l;
    l.centre = 0.5 * (lower.centre() + upper.centre());
    l.centre.z() = lower.centre().z();  // the landing is level with the nosing in front of it
    l.length_m = spacing;
    l.width_m = 0.5 * (lower.length() + upper.length());
    return l;
}

}  // namespace

FlightGeometry measureFlight(const StaircaseLandmark& landmark, double landing_run_factor) {
    const Staircase& s = landmark.stairs;
    FlightGeometry g;
    g.rise_m = s.step_height;
    g.run_m = s.step_depth;
    g.width_m = s.step_width;
    g.slope_deg = s.slope_rad * 180.0 / M_PI;
    g.heading_rad = s.heading_rad;
    g.risers = static_cast<int>(s.steps.size());
    const Eigen::Vector2d up = headingVector(s.heading_rad);

    const std::vector<double> gaps = spacings(s.steps, up);
    const double landing_gap = gaps.empty() ? 0.0 : landing_run_factor * upperMedian(gaps);
    std::vector<double> rises, runs, widths;
    int risers_in_run = 1;  // the first nosing tops the first riser
    g.max_risers_between_landings = 1;
    g.length_m = s.step_height;
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        const StairEdge& lower = s.steps[i];
        const StairEdge& upper = s.steps[i + 1];
        rises.push_back(upper.centre().z() - lower.centre().z());
        g.length_m += (upper.centre() - lower.centre()).norm();
        if (gaps.size() >= 2 && gaps[i] > landing_gap) {
            g.mid_landings.push_back(landingBetween(lower, upper, gaps[i]));
            risers_in_run = 1;
        } else {
            runs.push_back(gaps[i]);
            ++risers_in_run;
        }
        g.max_risers_between_landings = std::max(g.max_risers_between_landings, risers_in_run);
    }
    for (const StairEdge& e : s.steps) widths.push_back(e.length());
    g.rise_std_m = sampleStd(rises);
    g.run_std_m = sampleStd(runs);
    g.width_std_m = sampleStd(widths);
    g.bottom = s.steps.front().centre() - Eigen::Vector3d(0.0, 0.0, s.step_height);
    g.top = s.steps.back().centre();
    g.observed_risers = g.risers;
    return g;
}

void extendToFloors(FlightGeometry& g, double bottom_z, double top_z) {
    if (!(g.rise_m > 0.0)) return;
    const Eigen::Vector2d up = headingVector(g.heading_rad);
    const double step_length = std::hypot(g.rise_m, g.run_m);
    // Missing rises at each end (continuous), the position moves along the slope by as much.
    const auto slide = [&](Eigen::Vector3d& end, double dz) {
        end.head<2>() += (dz / g.rise_m) * g.run_m * up;
        end.z() += dz;
        g.length_m += std::abs(dz / g.rise_m) * step_length;
    };
    const int first_run =
        g.mid_landings.empty() ? g.risers : 0;  // only the whole flight is one run
    const auto rises = [&g](double dz) { return static_cast<int>(std::lround(dz / g.rise_m)); };
    if (std::isfinite(bottom_z) && g.bottom.z() - bottom_z > 0.5 * g.rise_m) {
        g.inferred_risers_bottom = rises(g.bottom.z() - bottom_z);
        slide(g.bottom, bottom_z - g.bottom.z());
    }
    if (std::isfinite(top_z) && top_z - g.top.z() > 0.5 * g.rise_m) {
        g.inferred_risers_top = rises(top_z - g.top.z());
        // With both floors known the whole height counts the risers: one rounding, not one per
        // end plus the seen nosings' height errors.
        if (std::isfinite(bottom_z)) {
            g.inferred_risers_top =
                std::max(0, rises(top_z - bottom_z) - g.observed_risers - g.inferred_risers_bottom);
        }
        slide(g.top, top_z - g.top.z());
    }
    const int added = g.inferred_risers_bottom + g.inferred_risers_top;
    g.risers += added;
    // Unseen risers join the runs at the ends they continue (the whole flight without landings).
    if (first_run > 0)
        g.max_risers_between_landings += added;
    else
        g.max_risers_between_landings += std::max(g.inferred_risers_bottom, g.inferred_risers_top);
}

}  // namespace stairmap::exporting
