#include "io/eval/EvalJson.h"

#include <cstdio>
#include <sstream>

namespace stairmap::io {

namespace {
using nlohmann::json;

json rowJson(const KindSummary& r) {
    return {{"kind", r.kind},
            {"clouds", r.clouds},
            {"samples", r.samples},
            {"detections", r.detections},
            {"false_positives", r.false_positives},
            {"false_positives_on_flights", r.false_positives_on_flights},
            {"mae_height_cm", r.mae_height_cm},
            {"mae_depth_cm", r.mae_depth_cm},
            {"mae_width_cm", r.mae_width_cm},
            {"mae_location_cm", r.mae_location_cm},
            {"mae_start_cm", r.mae_start_cm},
            {"bounded", r.bounded},
            {"mae_width_bounded_cm", r.mae_width_bounded_cm},
            {"mean_time_ms", r.mean_time_ms ? json(*r.mean_time_ms) : json(nullptr)}};
}

json sampleJson(const SampleOutcome& s) {
    json errors = json::array();
    for (const auto& e : s.errors) {
        errors.push_back({{"height_cm", e.height_cm},
                          {"depth_cm", e.depth_cm},
                          {"width_cm", e.width_cm},
                          {"location_cm", e.location_cm},
                          {"start_cm", e.start_cm},
                          {"both_sides_bounded", e.both_sides_bounded}});
    }
    return {{"name", s.name},
            {"kind", s.kind},
            {"expected", s.expected},
            {"matched", s.matched},
            {"false_positives", s.false_positives},
            {"false_positives_on_flights", s.false_positives_on_flights},
            {"missed", s.missed},
            {"errors", errors}};
}

std::string rowText(const KindSummary& r) {
    char mae[128];
    if (r.detections > 0) {
        std::snprintf(mae, sizeof(mae), "%8.2f %8.2f %8.2f %10.2f %7.2f", r.mae_height_cm,
                      r.mae_depth_cm, r.mae_width_cm, r.mae_location_cm, r.mae_start_cm);
    } else {
        std::snprintf(mae, sizeof(mae), "%8s %8s %8s %10s %7s", "-", "-", "-", "-", "-");
    }
    char time[32];
    if (r.mean_time_ms) std::snprintf(time, sizeof(time), "%9.1f", *r.mean_time_ms);
    else std::snprintf(time, sizeof(time), "%9s", "-");
    char bounded[48];
    if (r.bounded > 0) std::snprintf(bounded, sizeof(bounded), "%8d %9.2f", r.bounded, r.mae_width_bounded_cm);
    else std::snprintf(bounded, sizeof(bounded), "%8d %9s", 0, "-");
    char line[320];
    std::snprintf(line, sizeof(line), "%-12s %6d %7d %9d %6d  %s %s %s\n", r.kind.c_str(), r.clouds,
                  r.samples, r.detections, r.false_positives, mae, time, bounded);
    return line;
}
}  // namespace

json evaluationToJson(const EvaluationReport& report, const EvaluationParams& params) {
    json kinds = json::array();
    for (const auto& k : report.kinds) kinds.push_back(rowJson(k));
    json samples = json::array();
    for (const auto& s : report.samples) samples.push_back(sampleJson(s));
    return {{"params", {{"max_xy_m", params.max_xy_m}, {"max_z_m", params.max_z_m}}},
            {"kinds", kinds},
            {"total", rowJson(report.total)},
            {"samples", samples}};
}

std::string formatEvaluationTable(const EvaluationReport& report) {
    std::ostringstream out;
    // "start": height of the surface the flight starts from (flightStartZ). The last two columns:
    // matched flights with both sides bounded (wall or open edge seen) and their width MAE: the
    // width of a flight with an unseen side may be short by what was not seen.
    out << "kind         clouds samples detected FP     height    depth    width   location   start  time/det  bounded   width\n"
        << "                                            MAE cm   MAE cm   MAE cm     MAE cm  MAE cm        ms   sides   MAE cm\n";
    for (const auto& k : report.kinds) out << rowText(k);
    out << rowText(report.total);
    // Which false positives a fix of the readings would turn into matches, and which lie where no
    // flight is.
    out << "false positives on true flights (heights misread, or a flight read twice): "
        << report.total.false_positives_on_flights << " of " << report.total.false_positives
        << "\n";
    return out.str();
}

}  // namespace stairmap::io
