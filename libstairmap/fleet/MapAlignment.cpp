#include "fleet/MapAlignment.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "fleet/StaircasePairing.h"

namespace stairmap::fleet {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

/// One staircase of `other` laid on one of `first` by a transform, with its coinciding nosings.
struct Inlier {
    int a = -1, b = -1;  ///< indices into the flight views
    std::vector<StepPair> steps;
};

struct Hypothesis {
    TransformFit fit;
    std::vector<Inlier> inliers;
    int steps = 0;
};

struct Views {
    std::vector<FlightView> first, other;
};

/// Staircase pairs the transform lays on each other, one to one (most coinciding nosings first).
std::vector<Inlier> consensus(const Views& v, const Transform4& T, const AlignmentParams& p) {
    std::vector<Inlier> candidates;
    for (std::size_t j = 0; j < v.other.size(); ++j) {
        const FlightView moved = transformFlight(v.other[j], T);
        for (std::size_t i = 0; i < v.first.size(); ++i) {
            if (!shapesAgree(v.first[i].stairs, moved.stairs, p)) continue;
            std::vector<StepPair> steps = coincidingSteps(v.first[i].stairs, moved.stairs, p);
            if (static_cast<int>(steps.size()) < p.min_overlap_steps) continue;
            if (!endsConsistent(v.first[i], moved, p)) continue;
            candidates.push_back({static_cast<int>(i), static_cast<int>(j), std::move(steps)});
        }
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const Inlier& x, const Inlier& y) {
        return x.steps.size() > y.steps.size();
    });
    std::vector<Inlier> inliers;
    std::set<int> used_a, used_b;
    for (Inlier& c : candidates) {
        if (used_a.count(c.a) || used_b.count(c.b)) continue;
        used_a.insert(c.a);
        used_b.insert(c.b);
        inliers.push_back(std::move(c));
    }
    return inliers;
}

std::vector<EdgeCorrespondence> correspondences(const Views& v, const std::vector<Inlier>& inliers) {
    std::vector<EdgeCorrespondence> out;
    for (const Inlier& in : inliers) {
        for (const StepPair& s : in.steps) {
            out.push_back({v.first[in.a].stairs.steps[s.first], v.other[in.b].stairs.steps[s.other]});
        }
    }
    return out;
}

/// Least-squares refit on every coinciding nosing, twice (the inlier set may grow).
Hypothesis refine(const Views& v, TransformFit fit, const AlignmentParams& p) {
    Hypothesis h;
    h.fit = fit;
    for (int round = 0; round < 2; ++round) {
        std::vector<Inlier> inliers = consensus(v, h.fit.T_first_other, p);
        const std::vector<EdgeCorrespondence> pairs = correspondences(v, inliers);
        if (pairs.empty()) break;
        h.fit = fitTransform4(pairs, p);
        h.inliers = consensus(v, h.fit.T_first_other, p);
    }
    h.steps = 0;
    for (const Inlier& in : h.inliers) h.steps += static_cast<int>(in.steps.size());
    return h;
}

bool distinct(const Transform4& x, const Transform4& y, const AlignmentParams& p) {
    const double t = p.distinct_translation_m;
    return std::abs(x.x - y.x) > t || std::abs(x.y - y.y) > t || std::abs(x.z - y.z) > t ||
           std::abs(wrapAngle(x.yaw_rad - y.yaw_rad)) > p.distinct_yaw_deg * kDegToRad;
}

/// Every proposal: one per shape-compatible pair and whole-step shift, refined.
std::vector<Hypothesis> hypotheses(const Views& v, const AlignmentParams& p) {
    std::vector<Hypothesis> out;
    for (const FlightView& a : v.first) {
        for (const FlightView& b : v.other) {
            if (!shapesAgree(a.stairs, b.stairs, p)) continue;
            for (int shift : candidateShifts(a, b, p)) {
                std::vector<EdgeCorrespondence> pairs;
                for (const StepPair& s : stepPairsAtShift(a.stairs, b.stairs, shift))
                    pairs.push_back({a.stairs.steps[s.first], b.stairs.steps[s.other]});
                Hypothesis h = refine(v, fitTransform4(pairs, p), p);
                if (!h.inliers.empty()) out.push_back(std::move(h));
            }
        }
    }
    return out;
}

AlignmentResult toResult(const Views& v, const Hypothesis& h) {
    AlignmentResult r;
    r.status = AlignmentStatus::Aligned;
    r.T_first_other = h.fit.T_first_other;
    r.sigma = h.fit.sigma;
    r.matched_steps = h.steps;
    r.rms_perp_m = h.fit.rms_perp_m;
    for (const Inlier& in : h.inliers) r.pairs.push_back({v.first[in.a].id, v.other[in.b].id});
    std::sort(r.pairs.begin(), r.pairs.end(),
              [](const LandmarkPair& x, const LandmarkPair& y) { return x.first_id < y.first_id; });
    return r;
}

bool better(const Hypothesis& x, const Hypothesis& y) {
    if (x.inliers.size() != y.inliers.size()) return x.inliers.size() > y.inliers.size();
    if (x.steps != y.steps) return x.steps > y.steps;
    return x.fit.rms_perp_m < y.fit.rms_perp_m;
}

}  // namespace

AlignmentResult estimateAlignment(const LandmarkMapState& first, const LandmarkMapState& other,
                                  const AlignmentParams& params) {
    params.validate();
    const Views v{flightViews(first), flightViews(other)};
    std::vector<Hypothesis> hyps = hypotheses(v, params);
    AlignmentResult r;
    if (hyps.empty()) {
        r.reason = "no staircase of the two maps agrees in rise, run, width and turn with "
                   "overlapping nosings (no shared staircase)";
        return r;
    }
    std::sort(hyps.begin(), hyps.end(), better);
    const Hypothesis& best = hyps.front();
    std::vector<Transform4> rivals;
    for (const Hypothesis& h : hyps) {
        if (h.inliers.size() != best.inliers.size()) break;
        const Transform4& T = h.fit.T_first_other;
        const bool known = std::any_of(rivals.begin(), rivals.end(), [&](const Transform4& x) {
            return !distinct(x, T, params);
        });
        if (distinct(T, best.fit.T_first_other, params) && !known) rivals.push_back(T);
    }
    if (!rivals.empty()) {
        r.status = AlignmentStatus::Ambiguous;
        r.alternatives = rivals;
        r.alternatives.insert(r.alternatives.begin(), best.fit.T_first_other);
        r.reason = std::to_string(r.alternatives.size()) + " different transforms each explain " +
                   std::to_string(best.inliers.size()) +
                   " shared staircase(s) (a flight seen partially in both maps repeats every "
                   "step unless both saw the same end; identical flights are interchangeable)";
        return r;
    }
    return toResult(v, best);
}

AlignmentResult evaluateAlignment(const LandmarkMapState& first, const LandmarkMapState& other,
                                  const Transform4& T_first_other, const AlignmentParams& params) {
    params.validate();
    const Views v{flightViews(first), flightViews(other)};
    Hypothesis h;
    h.fit.T_first_other = T_first_other;
    h.inliers = consensus(v, T_first_other, params);
    for (const Inlier& in : h.inliers) h.steps += static_cast<int>(in.steps.size());
    AlignmentResult r = toResult(v, h);
    r.T_first_other = T_first_other;  // given, not estimated
    if (h.inliers.empty()) {
        r.status = AlignmentStatus::NoSharedStaircase;
        r.reason = "no staircase coincides under the given transform";
        return r;
    }
    const TransformFit fit = fitTransform4(correspondences(v, h.inliers), params);
    r.sigma = fit.sigma;  // how well the given transform is supported by the nosings
    r.rms_perp_m = fit.rms_perp_m;
    return r;
}

}  // namespace stairmap::fleet
