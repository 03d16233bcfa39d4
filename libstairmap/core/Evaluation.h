#pragma once
// Scoring detections against ground truth (the paper's Tables I and II).
//
// Matching rule. A detection D can match a true staircase G when
//   1. the direction agrees with how the observer sees G (G.seen_as; skipped when unset, e.g. for
//      a world-frame landmark map), and
//   2. D's edges lie on G's nosings: for each edge of D take its centre c and the G nosing whose
//      segment is nearest to c in 3D; the MEDIAN over D's edges of the horizontal distance (c to
//      that segment, in xy) is below max_xy_m and the MEDIAN of |c.z - nosing z| is below max_z_m.
// Candidate pairs are then assigned greedily by increasing cost (median xy + median z): each true
// staircase and each detection is used at most once. Detections left over are false positives
// (a second detection of an already matched staircase is a false positive too); true staircases
// left over are misses. A false positive whose edges meet rule 1 and the xy half of rule 2 for some
// expected staircase lies on a true flight: that flight read with its heights off (max_z_m or
// more), or read twice. The rest lie where no flight is. Only true staircases with seen_as set (or
// all of them when the truth has no observer, i.e. frame "world") are expected to be found.
//
// Errors of a matched pair: |step_height - rise|, |step_depth - run|, |step_width - width| [cm],
// and the location error = distance [cm] from D.location (centre of D's first edge) to the segment
// of the nosing D should start with: G's lowest nosing for an ascending detection, its highest
// nosing for a descending one; the start error = |flightStartZ(D) - G's start| [cm], G's start
// being the surface the flight starts from as D meets it: bottom_z for an ascending D, top_z for a
// descending one (a flight off a platform or landing above or below the observer's floor too).

#include <optional>
#include <string>
#include <vector>

#include "core/GroundTruth.h"
#include "core/Staircase.h"

namespace stairmap {

struct EvaluationParams {
    double max_xy_m = 0.15;  ///< [m] median horizontal distance of edge centres to nosings
    double max_z_m = 0.06;   ///< [m] median vertical distance of edge centres to nosings
};

/// One scored unit: a cloud (or a map) with its truth and what was detected in it.
struct EvaluationSample {
    std::string name;                 ///< e.g. the cloud's file name
    std::string kind;                 ///< table row (stair kind name, or "negative")
    SceneTruth truth;                 ///< same frame as `detections`
    std::vector<Staircase> detections;
    std::optional<double> time_ms;    ///< detector run time for this sample [ms], if known
};

struct PairErrors {
    double height_cm = 0.0;
    double depth_cm = 0.0;
    double width_cm = 0.0;
    double location_cm = 0.0;
    double start_cm = 0.0;  ///< height error of the surface the flight starts from
    /// the detection marks both sides bounded (StairSide Wall or Open): its width is complete
    bool both_sides_bounded = false;
};

struct SampleOutcome {
    std::string name;
    std::string kind;
    int expected = 0;                 ///< true staircases to find
    int matched = 0;
    int false_positives = 0;
    /// of them, those lying on an expected true staircase (a flight misread or read twice)
    int false_positives_on_flights = 0;
    std::vector<PairErrors> errors;   ///< one per matched pair
    std::vector<std::string> missed;  ///< names of unmatched true staircases
};

/// One row of the table: sums and means over the samples of one kind.
struct KindSummary {
    std::string kind;
    int clouds = 0;                   ///< samples of this kind
    int samples = 0;                  ///< true staircases expected (Table II "Samples")
    int detections = 0;               ///< of them matched (Table II "Detection")
    int false_positives = 0;
    int false_positives_on_flights = 0;  ///< of them, on a true flight (SampleOutcome)
    double mae_height_cm = 0.0;       ///< means over matched pairs (0 when none)
    double mae_depth_cm = 0.0;
    double mae_width_cm = 0.0;
    double mae_location_cm = 0.0;
    double mae_start_cm = 0.0;        ///< start height (flightStartZ) vs the truth's bottom/top
    int bounded = 0;                  ///< matched detections with both sides bounded
    double mae_width_bounded_cm = 0.0;  ///< width MAE over those (0 when none)
    std::optional<double> mean_time_ms;  ///< mean detector time per sample (Table I)
};

struct EvaluationReport {
    std::vector<SampleOutcome> samples;
    std::vector<KindSummary> kinds;   ///< paper order: ascending, hollow, spiral, descending, debris,
                                      ///< negative, then any other label
    KindSummary total;                ///< kind "all"
};

/// Median xy and z distance of a detection's edge centres to the staircase's nosings [m].
struct EdgeDistances {
    double median_xy_m = 0.0;
    double median_z_m = 0.0;
};
EdgeDistances edgeDistances(const Staircase& detection, const StaircaseTruth& truth);

/// Scores one sample with the matching rule above.
SampleOutcome evaluateSample(const EvaluationSample& sample, const EvaluationParams& params = {});

/// Scores all samples and aggregates them per kind. Throws std::invalid_argument for bad params.
EvaluationReport evaluate(const std::vector<EvaluationSample>& samples,
                          const EvaluationParams& params = {});

}  // namespace stairmap
