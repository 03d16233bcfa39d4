// One flight's nosings read both ways (ascending away from the robot, descending towards it):
// the longer reading is kept; flights that share no edges stay.
#include "core/ReverseReadings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.14, kRun = 0.26, kWidth = 1.4;

/// Nosings k = first..last of a flight rising along +x from x0 (nosing k at x0 + k run, z0 + k
/// rise), read ascending (steps bottom to top) or descending towards the robot (top to bottom).
Staircase reading(int first, int last, StairDirection dir, double x0 = 5.5, double y_c = 0.0) {
    Staircase s;
    s.direction = dir;
    for (int k = first; k <= last; ++k) {
        StairEdge e;
        const double x = x0 + k * kRun, z = -0.73 + k * kRise;
        e.start = {x, y_c + kWidth / 2, z};
        e.end = {x, y_c - kWidth / 2, z};
        e.num_points = 25;
        s.steps.push_back(e);
    }
    if (dir == StairDirection::Descending) std::reverse(s.steps.begin(), s.steps.end());
    s.heading_rad = dir == StairDirection::Ascending ? 0.0 : M_PI;
    estimateGeometry(s);
    return s;
}

/// Nosings down_first..down_last read descending and up_first..up_last ascending: one is dropped;
/// the direction and step count of the one kept.
std::pair<StairDirection, std::size_t> kept(int down_first, int down_last, int up_first,
                                            int up_last) {
    std::vector<Staircase> flights = {reading(down_first, down_last, StairDirection::Descending),
                                      reading(up_first, up_last, StairDirection::Ascending)};
    EXPECT_EQ(dropReverseReadings(flights), 1);
    if (flights.size() != 1u) return {StairDirection::Ascending, 0};
    return {flights[0].direction, flights[0].steps.size()};
}

TEST(ReverseReadings, TheShorterReadingOfOneFlightIsDropped) {
    // a pit's flight: six nosings ascending, its lower three read descending towards the robot
    EXPECT_EQ(kept(0, 2, 0, 5), std::make_pair(StairDirection::Ascending, std::size_t{6}));
    // a longer descending reading is kept
    EXPECT_EQ(kept(0, 5, 3, 5), std::make_pair(StairDirection::Descending, std::size_t{6}));
}

TEST(ReverseReadings, OnATieTheAscendingReadingIsKept) {
    EXPECT_EQ(kept(0, 3, 0, 3), std::make_pair(StairDirection::Ascending, std::size_t{4}));
}

TEST(ReverseReadings, FlightsSharingNoEdgesStay) {
    // beside each other (2 m apart), at other heights along one line, or one shared edge only
    std::vector<Staircase> beside = {reading(0, 3, StairDirection::Descending, 5.5, 2.0),
                                     reading(0, 3, StairDirection::Ascending)};
    EXPECT_EQ(dropReverseReadings(beside), 0);
    std::vector<Staircase> beyond = {reading(0, 3, StairDirection::Descending, 9.0),
                                     reading(0, 3, StairDirection::Ascending)};
    EXPECT_EQ(dropReverseReadings(beyond), 0);
    std::vector<Staircase> one_edge = {reading(3, 6, StairDirection::Descending),
                                       reading(0, 3, StairDirection::Ascending)};
    EXPECT_EQ(dropReverseReadings(one_edge), 0);
    EXPECT_EQ(one_edge.size(), 2u);
    // two flights of one direction are Algorithm 2's business, not this
    std::vector<Staircase> same = {reading(0, 2, StairDirection::Ascending),
                                   reading(0, 5, StairDirection::Ascending)};
    EXPECT_EQ(dropReverseReadings(same), 0);
}

}  // namespace
}  // namespace stairmap
