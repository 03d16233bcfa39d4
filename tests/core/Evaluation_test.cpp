// Evaluation on hand-built detections with known errors, a missed staircase and false positives.

#include <gtest/gtest.h>

#include "core/Evaluation.h"

namespace stairmap {
namespace {

/// Ascending flight in the robot frame: 4 nosings at x = 2 + 0.3 (i-1), z = -0.4 + 0.2 i, y in
/// [-0.5, 0.5]; floor at z = -0.4.
StaircaseTruth flight(std::optional<StairDirection> seen_as) {
    StaircaseTruth s;
    s.name = "flight";
    s.rise_m = 0.2;
    s.run_m = 0.3;
    s.width_m = 1.0;
    s.num_risers = 4;
    s.bottom_z = -0.4;
    s.top_z = 0.4;
    s.seen_as = seen_as;
    for (int i = 1; i <= 4; ++i) {
        const double x = 2.0 + 0.3 * (i - 1), z = -0.4 + 0.2 * i;
        s.nosings.push_back({{x, -0.5, z}, {x, 0.5, z}});
    }
    return s;
}

SceneTruth robotTruth(std::vector<StaircaseTruth> stairs) {
    SceneTruth t;
    t.frame = "robot";
    t.staircases = std::move(stairs);
    t.observer_floor_z = -0.4;
    return t;
}

/// Detection whose edges lie on the given nosings (in that order), half-width `half_width`.
Staircase detectionOn(const StaircaseTruth& truth, StairDirection dir, double half_width,
                      const Eigen::Vector3d& shift = Eigen::Vector3d::Zero()) {
    Staircase d;
    d.direction = dir;
    auto nosings = truth.nosings;
    if (dir == StairDirection::Descending) std::reverse(nosings.begin(), nosings.end());
    for (const auto& n : nosings) {
        StairEdge e;
        const Eigen::Vector3d c = n.centre() + shift;
        e.start = c - Eigen::Vector3d(0, half_width, 0);
        e.end = c + Eigen::Vector3d(0, half_width, 0);
        d.steps.push_back(e);
    }
    d.location = d.steps.front().centre();
    return d;
}

std::vector<EvaluationSample> handBuiltSamples() {
    std::vector<EvaluationSample> samples(4);
    // 1: ascending, found with errors height 1, depth 2, width 10, location 3 cm + one far-away FP.
    samples[0].name = "asc_found";
    samples[0].kind = "ascending";
    samples[0].truth = robotTruth({flight(StairDirection::Ascending)});
    Staircase good = detectionOn(samples[0].truth.staircases[0], StairDirection::Ascending, 0.45);
    good.step_height = 0.21;
    good.step_depth = 0.28;
    good.step_width = 0.90;
    good.location += Eigen::Vector3d(-0.03, 0, 0);
    Staircase far = detectionOn(samples[0].truth.staircases[0], StairDirection::Ascending, 0.45,
                                Eigen::Vector3d(8, 0, 0));
    samples[0].detections = {far, good};
    samples[0].time_ms = 10.0;
    // 2: ascending, missed.
    samples[1].name = "asc_missed";
    samples[1].kind = "ascending";
    samples[1].truth = robotTruth({flight(StairDirection::Ascending)});
    samples[1].time_ms = 20.0;
    // 3: descending, found (height 3, location 1 cm) + the same edges reported as ascending (FP).
    samples[2].name = "desc_found";
    samples[2].kind = "descending";
    samples[2].truth = robotTruth({flight(StairDirection::Descending)});
    Staircase down = detectionOn(samples[2].truth.staircases[0], StairDirection::Descending, 0.5);
    down.step_height = 0.17;
    down.step_depth = 0.30;
    down.step_width = 1.00;
    down.location += Eigen::Vector3d(0, 0, 0.01);
    Staircase wrong_way = detectionOn(samples[2].truth.staircases[0], StairDirection::Ascending, 0.5);
    samples[2].detections = {wrong_way, down};
    samples[2].time_ms = 30.0;
    // 4: negative scene with one detection.
    samples[3].name = "neg";
    samples[3].kind = "negative";
    samples[3].truth = robotTruth({});
    samples[3].detections = {far};
    samples[3].time_ms = 40.0;
    return samples;
}

const KindSummary& row(const EvaluationReport& r, const std::string& kind) {
    for (const auto& k : r.kinds)
        if (k.kind == kind) return k;
    throw std::runtime_error("no row " + kind);
}

TEST(Evaluation, KnownErrorsMissesAndFalsePositives) {
    const auto report = evaluate(handBuiltSamples());
    ASSERT_EQ(report.kinds.size(), 3u);
    EXPECT_EQ(report.kinds[0].kind, "ascending");  // paper order
    EXPECT_EQ(report.kinds[1].kind, "descending");
    EXPECT_EQ(report.kinds[2].kind, "negative");

    const auto& asc = row(report, "ascending");
    EXPECT_EQ(asc.clouds, 2);
    EXPECT_EQ(asc.samples, 2);
    EXPECT_EQ(asc.detections, 1);
    EXPECT_EQ(asc.false_positives, 1);
    EXPECT_NEAR(asc.mae_height_cm, 1.0, 1e-9);
    EXPECT_NEAR(asc.mae_depth_cm, 2.0, 1e-9);
    EXPECT_NEAR(asc.mae_width_cm, 10.0, 1e-9);
    EXPECT_NEAR(asc.mae_location_cm, 3.0, 1e-9);
    EXPECT_NEAR(*asc.mean_time_ms, 15.0, 1e-12);

    const auto& desc = row(report, "descending");
    EXPECT_EQ(desc.samples, 1);
    EXPECT_EQ(desc.detections, 1);
    EXPECT_EQ(desc.false_positives, 1);  // the wrong-direction detection
    EXPECT_NEAR(desc.mae_height_cm, 3.0, 1e-9);
    EXPECT_NEAR(desc.mae_depth_cm, 0.0, 1e-9);
    EXPECT_NEAR(desc.mae_width_cm, 0.0, 1e-9);
    EXPECT_NEAR(desc.mae_location_cm, 1.0, 1e-9);

    const auto& neg = row(report, "negative");
    EXPECT_EQ(neg.samples, 0);
    EXPECT_EQ(neg.false_positives, 1);

    EXPECT_EQ(report.total.clouds, 4);
    EXPECT_EQ(report.total.samples, 3);
    EXPECT_EQ(report.total.detections, 2);
    EXPECT_EQ(report.total.false_positives, 3);
    EXPECT_NEAR(report.total.mae_height_cm, 2.0, 1e-9);
    EXPECT_NEAR(report.total.mae_depth_cm, 1.0, 1e-9);
    EXPECT_NEAR(report.total.mae_width_cm, 5.0, 1e-9);
    EXPECT_NEAR(report.total.mae_location_cm, 2.0, 1e-9);
    EXPECT_NEAR(*report.total.mean_time_ms, 25.0, 1e-12);
    ASSERT_EQ(report.samples[1].missed.size(), 1u);
    EXPECT_EQ(report.samples[1].missed[0], "flight");
}

TEST(Evaluation, MatchingThresholdsOnEdgeDistances) {
    const auto truth = flight(StairDirection::Ascending);
    // 10 cm sideways of the nosings in x (beyond the segment's perpendicular): xy = 0.10 m.
    const auto shifted = detectionOn(truth, StairDirection::Ascending, 0.4, Eigen::Vector3d(0.1, 0, 0));
    const auto d = edgeDistances(shifted, truth);
    EXPECT_NEAR(d.median_xy_m, 0.1, 1e-9);
    EXPECT_NEAR(d.median_z_m, 0.0, 1e-9);
    EvaluationSample sample;
    sample.kind = "ascending";
    sample.truth = robotTruth({truth});
    sample.detections = {shifted};
    EvaluationParams strict;
    strict.max_xy_m = 0.05;
    EXPECT_EQ(evaluateSample(sample, strict).matched, 0);
    EXPECT_EQ(evaluateSample(sample, {}).matched, 1);
    // A 5 cm vertical offset passes the default 6 cm z gate; 8 cm does not.
    sample.detections = {detectionOn(truth, StairDirection::Ascending, 0.4, Eigen::Vector3d(0, 0, 0.05))};
    EXPECT_EQ(evaluateSample(sample, {}).matched, 1);
    sample.detections = {detectionOn(truth, StairDirection::Ascending, 0.4, Eigen::Vector3d(0, 0, 0.08))};
    EXPECT_EQ(evaluateSample(sample, {}).matched, 0);
}

TEST(Evaluation, DuplicateDetectionIsAFalsePositiveAndWorldTruthIgnoresDirection) {
    SceneTruth world;
    world.frame = "world";
    world.staircases = {flight(std::nullopt)};
    EvaluationSample sample;
    sample.kind = "ascending";
    sample.truth = world;
    const auto d = detectionOn(world.staircases[0], StairDirection::Descending, 0.5);
    sample.detections = {d, d};
    const auto out = evaluateSample(sample);
    EXPECT_EQ(out.expected, 1);
    EXPECT_EQ(out.matched, 1);
    EXPECT_EQ(out.false_positives, 1);
}

TEST(Evaluation, FalsePositivesOnTrueFlightsAreCountedApart) {
    // One ascending flight; detections: on it (matched), on it again (a second reading), on its
    // nosings' places 10 cm too high (heights misread), 1 m beside it, and on it the wrong way
    // (rule 1 fails: not a reading of this flight). Four false positives, two on the flight.
    EvaluationSample sample;
    sample.kind = "ascending";
    sample.truth = robotTruth({flight(StairDirection::Ascending)});
    const StaircaseTruth& truth = sample.truth.staircases[0];
    const Staircase on = detectionOn(truth, StairDirection::Ascending, 0.45);
    sample.detections = {
        on,
        on,
        detectionOn(truth, StairDirection::Ascending, 0.45, Eigen::Vector3d(0, 0, 0.10)),
        detectionOn(truth, StairDirection::Ascending, 0.45, Eigen::Vector3d(0, 1.0, 0)),
        detectionOn(truth, StairDirection::Descending, 0.45),
    };
    const SampleOutcome out = evaluateSample(sample);
    EXPECT_EQ(out.matched, 1);
    EXPECT_EQ(out.false_positives, 4);
    EXPECT_EQ(out.false_positives_on_flights, 2);
    const auto report = evaluate({sample, sample});
    EXPECT_EQ(report.total.false_positives, 8);
    EXPECT_EQ(report.total.false_positives_on_flights, 4);
    EXPECT_EQ(row(report, "ascending").false_positives_on_flights, 4);
}

TEST(Evaluation, EmptyInputAndBadParams) {
    const auto report = evaluate({});
    EXPECT_TRUE(report.kinds.empty());
    EXPECT_EQ(report.total.samples, 0);
    EXPECT_FALSE(report.total.mean_time_ms);
    EvaluationParams bad;
    bad.max_z_m = 0.0;
    EXPECT_THROW(evaluate({}, bad), std::invalid_argument);
}

TEST(Evaluation, WidthOfFlightsWithBothSidesBoundedIsReportedSeparately) {
    // two ascending samples: one bounded (wall / open), width off by 4 cm; one with an unseen
    // side, width off by 30 cm
    std::vector<EvaluationSample> samples(2);
    for (int i = 0; i < 2; ++i) {
        samples[i].name = "s" + std::to_string(i);
        samples[i].kind = "ascending";
        samples[i].truth = robotTruth({flight(StairDirection::Ascending)});
        Staircase d = detectionOn(samples[i].truth.staircases[0], StairDirection::Ascending, 0.5);
        d.step_height = 0.2;
        d.step_depth = 0.3;
        d.step_width = i == 0 ? 1.04 : 0.70;
        d.left_side = i == 0 ? StairSide::Wall : StairSide::Unseen;
        d.right_side = StairSide::Open;
        samples[i].detections = {d};
    }
    const EvaluationReport r = evaluate(samples);
    ASSERT_EQ(r.kinds.size(), 1u);
    EXPECT_EQ(r.total.detections, 2);
    EXPECT_EQ(r.total.bounded, 1);
    EXPECT_NEAR(r.total.mae_width_bounded_cm, 4.0, 1e-6);
    EXPECT_NEAR(r.total.mae_width_cm, 17.0, 1e-6);
    EXPECT_TRUE(r.samples[0].errors.at(0).both_sides_bounded);
    EXPECT_FALSE(r.samples[1].errors.at(0).both_sides_bounded);
}

TEST(Evaluation, StartHeightIsComparedWithTheSurfaceTheFlightStartsFrom) {
    // Truth: bottom_z -0.4 (the floor under the first nosing at -0.2), top_z 0.4.
    EvaluationSample up;
    up.name = "up";
    up.kind = "ascending";
    up.truth = robotTruth({flight(StairDirection::Ascending)});
    Staircase a = detectionOn(up.truth.staircases[0], StairDirection::Ascending, 0.45);
    a.step_height = 0.17;  // first edge at -0.2: the start is read at -0.37, 3 cm above the floor
    up.detections = {a};
    EvaluationSample down;
    down.name = "down";
    down.kind = "descending";
    down.truth = robotTruth({flight(StairDirection::Descending)});
    Staircase d = detectionOn(down.truth.staircases[0], StairDirection::Descending, 0.45,
                              Eigen::Vector3d(0, 0, -0.02));  // edges 2 cm low: top read at 0.38
    d.step_height = 0.2;
    down.detections = {d};
    const auto report = evaluate({up, down});
    ASSERT_EQ(report.samples[0].errors.size(), 1u);
    ASSERT_EQ(report.samples[1].errors.size(), 1u);
    EXPECT_NEAR(report.samples[0].errors[0].start_cm, 3.0, 1e-9);
    EXPECT_NEAR(report.samples[1].errors[0].start_cm, 2.0, 1e-9);
    EXPECT_NEAR(report.total.mae_start_cm, 2.5, 1e-9);
}

}  // namespace
}  // namespace stairmap
