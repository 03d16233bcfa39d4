#include "core/Evaluation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "core/StaircaseGeometry.h"

namespace stairmap {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::infinity();
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + mid, v.end());
    if (v.size() % 2 == 1) return v[mid];
    const double upper = v[mid];
    return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + mid));
}

/// Closest point of segment [a, b] to p, in the xy plane only (returns the segment parameter).
double closestParamXY(const NosingSegment& n, const Eigen::Vector3d& p) {
    const Eigen::Vector2d ab = (n.end - n.start).head<2>();
    const double len2 = ab.squaredNorm();
    if (len2 < 1e-12) return 0.0;
    return std::clamp(ab.dot((p - n.start).head<2>()) / len2, 0.0, 1.0);
}

double distanceToSegment(const NosingSegment& n, const Eigen::Vector3d& p) {
    const Eigen::Vector3d ab = n.end - n.start;
    const double len2 = ab.squaredNorm();
    const double t = len2 < 1e-12 ? 0.0 : std::clamp(ab.dot(p - n.start) / len2, 0.0, 1.0);
    return (n.start + t * ab - p).norm();
}

bool expected(const StaircaseTruth& stair, const SceneTruth& truth) {
    return stair.seen_as.has_value() || truth.frame == "world";
}

PairErrors pairErrors(const Staircase& d, const StaircaseTruth& g) {
    PairErrors e;
    e.height_cm = 100.0 * std::abs(d.step_height - g.rise_m);
    e.depth_cm = 100.0 * std::abs(d.step_depth - g.run_m);
    e.width_cm = 100.0 * std::abs(d.step_width - g.width_m);
    e.both_sides_bounded = d.left_side != StairSide::Unseen && d.right_side != StairSide::Unseen;
    const NosingSegment& first =
        d.direction == StairDirection::Ascending ? g.nosings.front() : g.nosings.back();
    e.location_cm = 100.0 * distanceToSegment(first, d.location);
    const double true_start = d.direction == StairDirection::Ascending ? g.bottom_z : g.top_z;
    if (!d.steps.empty()) e.start_cm = 100.0 * std::abs(flightStartZ(d) - true_start);
    return e;
}

int kindOrder(const std::string& kind) {
    static const std::vector<std::string> order = {"ascending", "hollow", "spiral",
                                                   "descending", "debris", "negative"};
    const auto it = std::find(order.begin(), order.end(), kind);
    return static_cast<int>(it - order.begin());
}
}  // namespace

EdgeDistances edgeDistances(const Staircase& detection, const StaircaseTruth& truth) {
    std::vector<double> xy, z;
    for (const auto& edge : detection.steps) {
        const Eigen::Vector3d c = edge.centre();
        double best = std::numeric_limits<double>::infinity();
        double best_xy = best, best_z = best;
        for (const auto& n : truth.nosings) {
            const double d3 = distanceToSegment(n, c);
            if (d3 >= best) continue;
            best = d3;
            const double t = closestParamXY(n, c);
            best_xy = ((n.start + t * (n.end - n.start)) - c).head<2>().norm();
            best_z = std::abs(c.z() - n.centre().z());
        }
        xy.push_back(best_xy);
        z.push_back(best_z);
    }
    return {median(xy), median(z)};
}

SampleOutcome evaluateSample(const EvaluationSample& sample, const EvaluationParams& params) {
    SampleOutcome out;
    out.name = sample.name;
    out.kind = sample.kind;
    const auto& stairs = sample.truth.staircases;
    std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;  // cost, det, gt
    // Detections meeting the direction and xy parts of the rule for some expected staircase,
    // whatever their heights: unmatched, they lie on a true flight.
    std::vector<bool> on_a_flight(sample.detections.size(), false);
    for (std::size_t g = 0; g < stairs.size(); ++g) {
        if (!expected(stairs[g], sample.truth) || stairs[g].nosings.empty()) continue;
        ++out.expected;
        for (std::size_t d = 0; d < sample.detections.size(); ++d) {
            const auto& det = sample.detections[d];
            if (stairs[g].seen_as && det.direction != *stairs[g].seen_as) continue;
            if (det.steps.empty()) continue;
            const auto dist = edgeDistances(det, stairs[g]);
            if (dist.median_xy_m >= params.max_xy_m) continue;
            on_a_flight[d] = true;
            if (dist.median_z_m < params.max_z_m)
                candidates.emplace_back(dist.median_xy_m + dist.median_z_m, d, g);
        }
    }
    std::sort(candidates.begin(), candidates.end());
    std::vector<bool> det_used(sample.detections.size(), false), gt_used(stairs.size(), false);
    for (const auto& [cost, d, g] : candidates) {
        if (det_used[d] || gt_used[g]) continue;
        det_used[d] = gt_used[g] = true;
        ++out.matched;
        out.errors.push_back(pairErrors(sample.detections[d], stairs[g]));
    }
    out.false_positives = static_cast<int>(std::count(det_used.begin(), det_used.end(), false));
    for (std::size_t d = 0; d < sample.detections.size(); ++d)
        out.false_positives_on_flights += !det_used[d] && on_a_flight[d];
    for (std::size_t g = 0; g < stairs.size(); ++g) {
        if (!gt_used[g] && expected(stairs[g], sample.truth)) out.missed.push_back(stairs[g].name);
    }
    return out;
}

namespace {
void accumulate(KindSummary& row, const SampleOutcome& s, const std::optional<double>& time_ms,
                int& timed, double& time_sum) {
    ++row.clouds;
    row.samples += s.expected;
    row.detections += s.matched;
    row.false_positives += s.false_positives;
    row.false_positives_on_flights += s.false_positives_on_flights;
    for (const auto& e : s.errors) {
        row.mae_height_cm += e.height_cm;
        row.mae_depth_cm += e.depth_cm;
        row.mae_width_cm += e.width_cm;
        row.mae_location_cm += e.location_cm;
        row.mae_start_cm += e.start_cm;
        if (e.both_sides_bounded) {
            ++row.bounded;
            row.mae_width_bounded_cm += e.width_cm;
        }
    }
    if (time_ms) {
        ++timed;
        time_sum += *time_ms;
    }
}

void finish(KindSummary& row, int timed, double time_sum) {
    if (row.detections > 0) {
        row.mae_height_cm /= row.detections;
        row.mae_depth_cm /= row.detections;
        row.mae_width_cm /= row.detections;
        row.mae_location_cm /= row.detections;
        row.mae_start_cm /= row.detections;
    }
    if (row.bounded > 0) row.mae_width_bounded_cm /= row.bounded;
    if (timed > 0) row.mean_time_ms = time_sum / timed;
}
}  // namespace

EvaluationReport evaluate(const std::vector<EvaluationSample>& samples, const EvaluationParams& params) {
    if (!(params.max_xy_m > 0) || !(params.max_z_m > 0))
        throw std::invalid_argument("max_xy_m/max_z_m: must be > 0");
    EvaluationReport report;
    std::map<std::string, std::tuple<KindSummary, int, double>> rows;
    auto& [total, total_timed, total_time] = rows["\x01all"];  // never collides with a kind name
    total.kind = "all";
    for (const auto& sample : samples) {
        report.samples.push_back(evaluateSample(sample, params));
        auto& [row, timed, time_sum] = rows[sample.kind];
        row.kind = sample.kind;
        accumulate(row, report.samples.back(), sample.time_ms, timed, time_sum);
        accumulate(total, report.samples.back(), sample.time_ms, total_timed, total_time);
    }
    for (auto& [key, entry] : rows) {
        auto& [row, timed, time_sum] = entry;
        finish(row, timed, time_sum);
        if (key != "\x01all") report.kinds.push_back(row);
    }
    report.total = std::get<0>(rows["\x01all"]);
    std::stable_sort(report.kinds.begin(), report.kinds.end(), [](const auto& a, const auto& b) {
        return kindOrder(a.kind) < kindOrder(b.kind);
    });
    return report;
}

}  // namespace stairmap
