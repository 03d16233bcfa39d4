// What RViz and planners receive for a known landmark map.
#include <gtest/gtest.h>

#include <cmath>

#include "ros2/LandmarkMarkers.h"
#include "ros2/LandmarkMessages.h"

namespace stairmap::ros2 {
namespace {

/// A straight flight going up along +y from (2, 1, 0): `n` nosings, rise 0.18 + 0.01 k, run 0.30,
/// width 1.2 (edge from x = 2.6 to 1.4, left to right facing uphill).
StaircaseLandmark flight(int id, int n, bool confirmed) {
    StaircaseLandmark l;
    l.id = id;
    l.confirmed = confirmed;
    l.observations = confirmed ? 4 : 1;
    double z = 0.0;
    for (int k = 0; k < n; ++k) {
        z += 0.18 + 0.01 * k;
        StairEdge e;
        e.start = Eigen::Vector3d(1.4, 1.0 + 0.3 * k, z);
        e.end = Eigen::Vector3d(2.6, 1.0 + 0.3 * k, z);
        l.stairs.steps.push_back(e);
        l.step_observations.push_back(l.observations);
    }
    l.stairs.heading_rad = M_PI / 2;
    l.stairs.step_height = 0.19;
    l.stairs.step_depth = 0.30;
    l.stairs.step_width = 1.2;
    l.stairs.location = l.stairs.steps.front().centre();
    return l;
}

TEST(LandmarkMarkers, EdgesBoxesAndLabelPerLandmarkNamespace) {
    const std::vector<StaircaseLandmark> map = {flight(3, 3, true), flight(8, 2, false)};
    const std::vector<MarkerSpec> markers = landmarkMarkers(map, false);
    ASSERT_EQ(markers.size(), 6u);
    const MarkerSpec& edges = markers[0];
    EXPECT_EQ(edges.ns, "staircase_3");
    EXPECT_EQ(edges.type, kLineList);
    ASSERT_EQ(edges.points.size(), 6u);  // start and end of 3 edges
    EXPECT_TRUE(edges.points[4].isApprox(Eigen::Vector3d(1.4, 1.6, 0.18 + 0.19 + 0.20)));
    EXPECT_GT(edges.rgba[1], edges.rgba[0]);  // confirmed: green
    const MarkerSpec& boxes = markers[1];
    EXPECT_EQ(boxes.type, kCubeList);
    ASSERT_EQ(boxes.points.size(), 3u);
    // box centres in world: half a run uphill (+y) of each nosing, half a rise below it
    const Eigen::Vector3d first_world = boxes.orientation * boxes.points[0] + boxes.position;
    EXPECT_TRUE(first_world.isApprox(Eigen::Vector3d(2.0, 1.15, 0.18 - 0.095), 1e-9)) << first_world.transpose();
    EXPECT_NEAR(boxes.scale.x(), 0.30, 1e-12);
    const MarkerSpec& label = markers[2];
    EXPECT_EQ(label.type, kTextViewFacing);
    EXPECT_EQ(label.text, "stair 3: 3 steps, rise 19.0 cm, run 30.0 cm, width 1.20 m (confirmed)");
    EXPECT_NEAR(label.position.z(), 0.57 + 0.5, 1e-9);
    EXPECT_EQ(markers[3].ns, "staircase_8");
    EXPECT_GT(markers[3].rgba[0], markers[3].rgba[1]);  // tentative: orange
    EXPECT_NE(markers[5].text.find("tentative"), std::string::npos);
    for (const MarkerSpec& m : markers) EXPECT_EQ(m.action, kAdd);
}

TEST(LandmarkMarkers, DeleteAllComesFirst) {
    const std::vector<MarkerSpec> markers = landmarkMarkers({flight(1, 2, true)}, true);
    ASSERT_EQ(markers.size(), 4u);
    EXPECT_EQ(markers[0].action, kDeleteAll);
    EXPECT_EQ(markers[0].ns, "");
    EXPECT_TRUE(landmarkMarkers({}, true).size() == 1);
}

TEST(LandmarkMessages, FlightDimensionsWithSpread) {
    const FlightDimensions d = flightDimensions(flight(1, 4, true).stairs);
    // rises between edges: 0.19, 0.20, 0.21 -> mean 0.20, sample sd 0.01
    EXPECT_NEAR(d.rise, 0.20, 1e-12);
    EXPECT_NEAR(d.rise_sigma, 0.01, 1e-12);
    EXPECT_NEAR(d.run, 0.30, 1e-12);
    EXPECT_NEAR(d.run_sigma, 0.0, 1e-12);
    EXPECT_NEAR(d.width, 1.2, 1e-12);
}

TEST(LandmarkMessages, StaircaseArrayCarriesWhatPlannersUse) {
    StaircaseLandmark l = flight(5, 3, true);
    l.first_seen_s = 100.25;
    l.last_seen_s = 107.5;
    l.bottom_floor = 0;
    l.top_floor = 1;
    l.stairs.steps[1].cov_rho_theta << 4e-4, 1e-5, 1e-5, 9e-4;
    Floor ground;
    ground.id = 0;
    ground.z = 0.0;
    ground.robot_samples = 7;
    ground.staircase_ends = 1;
    const StaircaseArrayMessage message({l}, {ground}, 107.5, "map");
    const auto& m = *message.sample();
    EXPECT_STREQ(m.header.frame_id, "map");
    ASSERT_EQ(m.staircases._length, 1u);
    const auto& s = m.staircases._buffer[0];
    EXPECT_EQ(s.id, 5);
    EXPECT_TRUE(s.confirmed);
    EXPECT_EQ(s.observations, 4);
    EXPECT_EQ(s.first_seen.sec, 100);
    EXPECT_EQ(s.first_seen.nanosec, 250000000u);
    EXPECT_NEAR(s.heading, M_PI / 2, 1e-12);
    EXPECT_NEAR(s.rise, 0.19, 1e-12);
    EXPECT_NEAR(s.rise_sigma, 0.01 / std::sqrt(2.0), 1e-12);  // rises 0.19, 0.20
    ASSERT_EQ(s.steps._length, 3u);
    EXPECT_EQ(s.steps._buffer[1].cov_rho_theta[3], 9e-4);
    EXPECT_EQ(s.steps._buffer[1].cov_rho_theta[1], 1e-5);
    EXPECT_EQ(s.steps._buffer[2].start.y, 1.6);
    EXPECT_EQ(s.steps._buffer[2].observations, 4);
    EXPECT_EQ(s.bottom_floor_id, 0);
    EXPECT_EQ(s.top_floor_id, 1);
    ASSERT_EQ(m.floors._length, 1u);
    EXPECT_EQ(m.floors._buffer[0].support, 8);
}

}  // namespace
}  // namespace stairmap::ros2

namespace stairmap::ros2 {
namespace {

TEST(LandmarkMessages, StaircaseArrayReadsBackIntoTheSameLandmarks) {
    StaircaseLandmark l = flight(6, 4, true);
    l.first_seen_s = 5.5;
    l.last_seen_s = 9.25;
    l.bottom_floor = 2;
    l.top_floor = 7;  // a floor the message does not carry: the link is dropped
    l.stairs.steps[2].cov_rho_theta << 1e-3, 2e-4, 2e-4, 5e-3;
    l.stairs.steps[2].num_points = 31;
    Floor f;
    f.id = 2;
    f.z = -0.5;
    f.robot_samples = 4;
    const StaircaseArrayMessage message({flight(1, 2, false), l}, {f}, 9.25, "map");
    const LandmarkMapState state = landmarkState(*message.sample());
    ASSERT_EQ(state.staircases.size(), 2u);
    const StaircaseLandmark& back = state.staircases[1];
    EXPECT_EQ(back.id, 6);
    EXPECT_EQ(state.next_landmark_id, 7);
    ASSERT_EQ(back.stairs.steps.size(), 4u);
    EXPECT_TRUE(back.stairs.steps[3].end.isApprox(l.stairs.steps[3].end));
    EXPECT_EQ(back.stairs.steps[2].cov_rho_theta, l.stairs.steps[2].cov_rho_theta);
    EXPECT_EQ(back.stairs.steps[2].num_points, 31);
    EXPECT_EQ(back.step_observations, l.step_observations);
    EXPECT_DOUBLE_EQ(back.last_seen_s, 9.25);
    EXPECT_EQ(back.bottom_floor, 2);
    EXPECT_EQ(back.top_floor, -1);
    EXPECT_TRUE(back.confirmed);
    ASSERT_EQ(state.floor_levels.size(), 1u);
    EXPECT_EQ(state.floor_levels[0].z, -0.5);
}

TEST(LandmarkMessages, MalformedStaircaseArrayIsRefusedWithTheLandmark) {
    const StaircaseArrayMessage message({flight(9, 2, true)}, {}, 1.0, "map");
    stairmap_msgs_msg_dds__StaircaseArray_ broken = *message.sample();
    stairmap_msgs_msg_dds__Staircase_ staircase = broken.staircases._buffer[0];
    staircase.steps._length = 0;
    broken.staircases._buffer = &staircase;
    try {
        landmarkState(broken);
        FAIL() << "accepted a staircase without steps";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("staircase 9"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace stairmap::ros2
