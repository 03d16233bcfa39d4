#pragma once
// Test helper: two robots' maps of one building with a known transform between their frames
// (built with tests/fleet/FleetTestMaps.h): three flights both saw, plus one only robot B saw
// and one only robot A saw (added later in a run).

#include "fleet/FleetTestMaps.h"

namespace stairmap::fleetlive::test {

using fleet::Transform4;
using fleet::test::FlightSpec;

inline FlightSpec flight(double x, double y, double heading_deg, double rise, double run) {
    FlightSpec f;
    f.foot = {x, y};
    f.heading_deg = heading_deg;
    f.rise = rise;
    f.run = run;
    f.first_level = 1;
    f.last_level = 8;
    f.bottom_observed = true;
    return f;
}

/// Shared flights 0..2, then B's own flight (id 3) when `with_b_only`.
inline std::vector<FlightSpec> sharedFlights() {
    return {flight(2.0, 0.8, 0.0, 0.18, 0.28), flight(14.0, 6.0, 120.0, 0.17, 0.26),
            flight(6.0, -5.0, 250.0, 0.19, 0.30)};
}
inline FlightSpec onlyB() { return flight(-10.0, 12.0, 45.0, 0.16, 0.32); }
inline FlightSpec onlyA() { return flight(20.0, -12.0, 200.0, 0.21, 0.24); }  // unlike every other flight

inline LandmarkMapState mapOf(const std::vector<FlightSpec>& specs) {
    std::vector<StaircaseLandmark> landmarks;
    for (std::size_t i = 0; i < specs.size(); ++i)
        landmarks.push_back(fleet::test::makeLandmark(specs[i], static_cast<int>(i)));
    return fleet::test::makeMap(landmarks);
}

/// Robot A's map (the fleet frame), optionally with A's own extra flight.
inline LandmarkMapState robotA(bool with_a_only = false) {
    auto specs = sharedFlights();
    if (with_a_only) specs.push_back(onlyA());
    return mapOf(specs);
}

/// Robot B's map in B's frame: p_A = T_A_B * p_B.
inline LandmarkMapState robotB(const Transform4& T_A_B) {
    auto specs = sharedFlights();
    specs.push_back(onlyB());
    return fleet::test::inOtherFrame(mapOf(specs), T_A_B);
}

}  // namespace stairmap::fleetlive::test
