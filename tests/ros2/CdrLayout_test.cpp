// What stairmap's ROS 2 messages look like on the wire: each sample, serialized by Cyclone, must
// equal plain little-endian CDR built here by hand from the Jazzy .msg field order (and Cyclone
// must decode the hand-built bytes back into the same values). A reordered or retyped field in
// idl/*.idl fails here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>

#include "StairmapMessages.h"
#include "ros2/CdrBytes.h"
#include "ros2/LandmarkMarkers.h"
#include "ros2/LandmarkMessages.h"
#include "ros2/MessageBuilders.h"

namespace stairmap::ros2 {
namespace {

using test::CdrBytes;
using test::CdrRoundTrip;

std::string topicName(const std::string& base) { return "rt/cdrtest/" + std::to_string(getpid()) + "/" + base; }

/// Cyclone may pad the body to a multiple of 4 (and say so in the options); nothing else differs.
void expectSameCdr(const std::vector<std::uint8_t>& expected, const std::vector<std::uint8_t>& got) {
    ASSERT_GE(got.size(), expected.size());
    ASSERT_LT(got.size() - expected.size(), 4u) << "expected " << expected.size() << " bytes, got " << got.size();
    EXPECT_EQ(got[0], 0x00);
    EXPECT_EQ(got[1], 0x01) << "not CDR_LE (XCDR1 little-endian)";
    for (std::size_t i = 4; i < expected.size(); ++i)
        ASSERT_EQ(int(expected[i]), int(got[i])) << "first difference at byte " << i;
}

void header(CdrBytes& b, int sec, unsigned nanosec, const std::string& frame) { b.i32(sec).u32(nanosec).str(frame); }

TEST(CdrLayout, PointCloud2OfTwoPoints) {
    const PointCloud points = {{1.0f, 2.0f, 3.0f}, {-4.5f, 0.25f, 8.0f}};
    const CloudMessage message(points, 12.5, "lidar");
    CdrBytes b;
    header(b, 12, 500000000u, "lidar");
    b.u32(1).u32(2);  // height, width
    b.u32(3);         // fields
    const char* names[] = {"x", "y", "z"};
    for (std::uint32_t i = 0; i < 3; ++i) b.str(names[i]).u32(4 * i).u8(7).u32(1);
    b.boolean(false).u32(12).u32(24);
    std::vector<std::uint8_t> data(24);
    std::memcpy(data.data(), points[0].data(), 12);
    std::memcpy(data.data() + 12, points[1].data(), 12);
    b.octets(data).boolean(true);

    CdrRoundTrip dds(&sensor_msgs_msg_dds__PointCloud2__desc, topicName("points"));
    expectSameCdr(b.bytes(), dds.bytesOf(message.sample()));
    sensor_msgs_msg_dds__PointCloud2_ back{};
    ASSERT_TRUE(dds.sampleOf(b.bytes(), &back));
    EXPECT_EQ(back.width, 2u);
    EXPECT_STREQ(back.header.frame_id, "lidar");
    ASSERT_EQ(back.fields._length, 3u);
    EXPECT_STREQ(back.fields._buffer[2].name, "z");
    EXPECT_EQ(back.fields._buffer[2].offset, 8u);
    const CloudDecodeResult decoded = decodePointCloud(cloudLayout(back), back.data._buffer, back.data._length);
    ASSERT_EQ(decoded.points.size(), 2u);
    EXPECT_EQ(decoded.points[1], points[1]);
    dds_sample_free(&back, &sensor_msgs_msg_dds__PointCloud2__desc, DDS_FREE_CONTENTS);
}

TEST(CdrLayout, Odometry) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(1.5, -2.0, 0.25);
    T.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const OdometryMessage message(T, 3.000000001, "odom", "base_link");
    CdrBytes b;
    header(b, 3, 1u, "odom");
    b.str("base_link");
    b.f64(1.5).f64(-2.0).f64(0.25);
    b.f64(0.0).f64(0.0).f64(std::sin(0.25)).f64(std::cos(0.25));
    for (int i = 0; i < 36; ++i) b.f64(0.0);
    for (int i = 0; i < 6 + 36; ++i) b.f64(0.0);  // twist and its covariance

    CdrRoundTrip dds(&nav_msgs_msg_dds__Odometry__desc, topicName("odom"));
    const auto got = dds.bytesOf(message.sample());
    // the quaternion goes through a rotation matrix: compare it to 1e-12, the rest exactly
    ASSERT_EQ(got.size(), b.bytes().size());
    nav_msgs_msg_dds__Odometry_ back{};
    ASSERT_TRUE(dds.sampleOf(got, &back));
    EXPECT_NEAR(back.pose.pose.orientation.z, std::sin(0.25), 1e-12);
    EXPECT_NEAR(back.pose.pose.orientation.w, std::cos(0.25), 1e-12);
    dds_sample_free(&back, &nav_msgs_msg_dds__Odometry__desc, DDS_FREE_CONTENTS);
    nav_msgs_msg_dds__Odometry_ hand{};
    ASSERT_TRUE(dds.sampleOf(b.bytes(), &hand));
    EXPECT_STREQ(hand.child_frame_id, "base_link");
    EXPECT_EQ(hand.header.stamp.sec, 3);
    EXPECT_EQ(hand.pose.pose.position.y, -2.0);
    Eigen::Isometry3d T_back;
    ASSERT_TRUE(odometryPose(hand, T_back));
    EXPECT_TRUE(T_back.isApprox(T, 1e-12));
    dds_sample_free(&hand, &nav_msgs_msg_dds__Odometry__desc, DDS_FREE_CONTENTS);
}

TEST(CdrLayout, MarkerArrayFollowsJazzysMarker) {
    MarkerSpec spec;
    spec.ns = "staircase_7";
    spec.id = 2;
    spec.type = kTextViewFacing;
    spec.position = Eigen::Vector3d(1, 2, 3);
    spec.scale = Eigen::Vector3d(0, 0, 0.2);
    spec.rgba = Eigen::Vector4f(0.5f, 0.25f, 1.0f, 1.0f);
    spec.points = {Eigen::Vector3d(4, 5, 6)};
    spec.text = "stair 7";
    const MarkerArrayMessage message({spec}, 20.0, "map");
    CdrBytes b;
    b.u32(1);
    header(b, 20, 0u, "map");
    b.str("staircase_7").i32(2).i32(9).i32(0);
    b.f64(1).f64(2).f64(3).f64(0).f64(0).f64(0).f64(1);  // pose
    b.f64(0).f64(0).f64(0.2);                            // scale
    b.f32(0.5f).f32(0.25f).f32(1.0f).f32(1.0f);          // color
    b.i32(0).u32(0).boolean(false);                      // lifetime, frame_locked
    b.u32(1).f64(4).f64(5).f64(6);                       // points
    b.u32(0);                                            // colors
    b.str("");                                           // texture_resource
    header(b, 0, 0u, "");                                // texture: header, format, data
    b.str("").u32(0);
    b.u32(0);                                            // uv_coordinates
    b.str("stair 7").str("");                            // text, mesh_resource
    b.str("").u32(0);                                    // mesh_file
    b.boolean(false);                                    // mesh_use_embedded_materials

    CdrRoundTrip dds(&visualization_msgs_msg_dds__MarkerArray__desc, topicName("markers"));
    expectSameCdr(b.bytes(), dds.bytesOf(message.sample()));
    visualization_msgs_msg_dds__MarkerArray_ back{};
    ASSERT_TRUE(dds.sampleOf(b.bytes(), &back));
    ASSERT_EQ(back.markers._length, 1u);
    EXPECT_STREQ(back.markers._buffer[0].text, "stair 7");
    EXPECT_EQ(back.markers._buffer[0].points._buffer[0].z, 6.0);
    dds_sample_free(&back, &visualization_msgs_msg_dds__MarkerArray__desc, DDS_FREE_CONTENTS);
}

TEST(CdrLayout, StaircaseArray) {
    StaircaseLandmark l;
    l.id = 4;
    l.confirmed = true;
    l.observations = 3;
    l.first_seen_s = 10.0;
    l.last_seen_s = 11.5;
    StairEdge e;
    e.start = Eigen::Vector3d(0, 0.5, 0.17);
    e.end = Eigen::Vector3d(0, -0.5, 0.17);
    e.cov_rho_theta << 1e-4, 2e-5, 2e-5, 3e-4;
    e.num_points = 40;
    l.stairs.steps = {e};
    l.stairs.step_height = 0.17;
    l.stairs.step_depth = 0.28;
    l.stairs.step_width = 1.0;
    l.stairs.location = e.centre();
    l.step_observations = {3};
    l.bottom_floor = 0;
    l.top_floor = -1;
    l.bottom_observed = true;
    Floor f;
    f.id = 0;
    f.z = 0.0;
    f.robot_samples = 5;
    const StaircaseArrayMessage message({l}, {f}, 11.5, "map");
    CdrBytes b;
    header(b, 11, 500000000u, "map");
    b.u32(1).i32(4).u8(0).boolean(true).i32(3);
    b.i32(10).u32(0).i32(11).u32(500000000u);
    b.f64(0).f64(0).f64(0.17);                            // location
    b.f64(0).f64(0);                                      // heading, slope
    b.f64(0.17).f64(0).f64(0.28).f64(0).f64(1.0).f64(0);  // rise, run, width and sigmas
    b.u32(1).f64(0).f64(0.5).f64(0.17).f64(0).f64(-0.5).f64(0.17);
    b.f64(1e-4).f64(2e-5).f64(2e-5).f64(3e-4).i32(40).i32(3);
    b.i32(0).i32(-1).boolean(true).boolean(false);
    b.u32(1).i32(0).f64(0.0).i32(5);

    CdrRoundTrip dds(&stairmap_msgs_msg_dds__StaircaseArray__desc, topicName("staircases"));
    expectSameCdr(b.bytes(), dds.bytesOf(message.sample()));
    stairmap_msgs_msg_dds__StaircaseArray_ back{};
    ASSERT_TRUE(dds.sampleOf(b.bytes(), &back));
    ASSERT_EQ(back.staircases._length, 1u);
    EXPECT_EQ(back.staircases._buffer[0].steps._buffer[0].num_points, 40);
    EXPECT_EQ(back.floors._buffer[0].support, 5);
    dds_sample_free(&back, &stairmap_msgs_msg_dds__StaircaseArray__desc, DDS_FREE_CONTENTS);
}

TEST(CdrLayout, TypeNamesAreRos2s) {
    EXPECT_STREQ(sensor_msgs_msg_dds__PointCloud2__desc.m_typename, "sensor_msgs::msg::dds_::PointCloud2_");
    EXPECT_STREQ(nav_msgs_msg_dds__Odometry__desc.m_typename, "nav_msgs::msg::dds_::Odometry_");
    EXPECT_STREQ(visualization_msgs_msg_dds__MarkerArray__desc.m_typename,
                 "visualization_msgs::msg::dds_::MarkerArray_");
    // keyless, and no XTypes type information (rmw_cyclonedds sends none)
    for (const dds_topic_descriptor_t* d :
         {&sensor_msgs_msg_dds__PointCloud2__desc, &nav_msgs_msg_dds__Odometry__desc,
          &visualization_msgs_msg_dds__MarkerArray__desc, &stairmap_msgs_msg_dds__StaircaseArray__desc}) {
        EXPECT_EQ(d->m_nkeys, 0u) << d->m_typename;
        EXPECT_EQ(d->m_flagset & DDS_TOPIC_XTYPES_METADATA, 0u) << d->m_typename;
        EXPECT_EQ(d->type_information.sz, 0u) << d->m_typename;
    }
}

}  // namespace
}  // namespace stairmap::ros2
