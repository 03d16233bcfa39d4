#pragma once
// Output of `stairmap eval`: the evaluation report as JSON and as a text table laid out like the
// paper's Tables I and II (per kind: samples, detections, false positives, MAE of height, depth,
// width and location in cm, time per detection in ms).

#include <nlohmann/json.hpp>
#include <string>

#include "core/Evaluation.h"

namespace stairmap::io {

/// {"params":{...}, "kinds":[row...], "total":row, "samples":[{name, kind, expected, matched,
///  false_positives, false_positives_on_flights, missed:[...], errors:[{height_cm, depth_cm,
///  width_cm, location_cm, start_cm, both_sides_bounded}]}]}
/// where row = {kind, clouds, samples, detections, false_positives, false_positives_on_flights,
/// mae_height_cm, mae_depth_cm, mae_width_cm, mae_location_cm, mae_start_cm, bounded,
/// mae_width_bounded_cm, mean_time_ms (null if unknown)}. false_positives_on_flights: of the
/// false positives, those lying on a true flight (core/Evaluation.h).

/// Fixed-width text table, one row per kind plus "all", then a line with how many of all false
/// positives lie on true flights.
nlohmann::json evaluationToJson(const EvaluationReport& report, const EvaluationParams& params);

std::string formatEvaluationTable(const EvaluationReport& report);

}  // namespace stairmap::io
