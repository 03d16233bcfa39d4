#pragma once
// Which staircases of two maps may be one flight, and which of their nosings may be one stair.
// Everything works on canonical landmarks (map/LandmarkTypes.h: ascending, steps bottom to top,
// start = left end facing uphill), each in its own map frame unless stated.
//
// Nosings of one flight are a lattice: level l sits l rises up and l runs along the flight. Two
// partial views of one flight therefore agree for every whole-step shift k that keeps some
// nosings overlapping; only an end seen by both maps (the bottom or the top of the flight) or a
// second staircase fixes k (docs/merge.md, "Ambiguity").

#include <limits>
#include <vector>

#include "core/Staircase.h"
#include "fleet/AlignmentParams.h"
#include "fleet/Transform4.h"
#include "map/LandmarkTypes.h"

namespace stairmap::fleet {

/// A landmark as the alignment sees it: the flight plus what is known about its ends.
struct FlightView {
    int id = -1;                ///< landmark id in its map
    Staircase stairs;           ///< canonical
    bool bottom_observed = false;
    bool top_observed = false;
    /// [m] z of the floor the flight leaves from (its linked bottom floor), NaN if unknown.
    double bottom_floor_z = std::numeric_limits<double>::quiet_NaN();
};

/// The flights of a map state (landmarks with at least one step), with floor heights looked up.
std::vector<FlightView> flightViews(const LandmarkMapState& state);

/// The view moved by T_to_from (steps, location, heading and the bottom floor's height).
FlightView transformFlight(const FlightView& view, const Transform4& T_to_from);

/// Index of a step in each flight.
struct StepPair {
    int first = -1;
    int other = -1;
};

/// Rise, run, width and turn per step agree within the tolerances (direction is implied: both
/// are canonical, uphill). Frame independent.
bool shapesAgree(const Staircase& a, const Staircase& b, const AlignmentParams& params);

/// [rad] mean change of edge direction from one step to the next (0 for a straight flight).
double meanTurnPerStep(const Staircase& stairs);

/// Level of each step above the flight's lowest seen nosing: round((z - z_lowest) / rise).
std::vector<int> stepLevels(const Staircase& stairs);

/// Whole-step shifts k (level l of `other` is level l + k of `first`) that keep at least
/// params.min_overlap_steps nosings overlapping and respect the ends both maps saw: one shift
/// when both saw the bottom (or both the top), else every shift allowed by the observed ends.
std::vector<int> candidateShifts(const FlightView& first, const FlightView& other,
                                 const AlignmentParams& params);

/// Step pairs of one shift: equal levels, one to one.
std::vector<StepPair> stepPairsAtShift(const Staircase& first, const Staircase& other, int shift);

/// Step pairs of two flights in the SAME frame (`other_in_first` already transformed): nosings
/// whose heights, lines and directions agree (params.match_*), one to one, nearest first.
std::vector<StepPair> coincidingSteps(const Staircase& first, const Staircase& other_in_first,
                                      const AlignmentParams& params);

/// The flights, in the same frame, do not contradict an end either map saw: nothing of one lies
/// above the other's observed top or below the other's observed bottom (half a rise of slack).
bool endsConsistent(const FlightView& first, const FlightView& other_in_first,
                    const AlignmentParams& params);

}  // namespace stairmap::fleet
