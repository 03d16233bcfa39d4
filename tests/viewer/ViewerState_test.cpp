// The viewer's state without a window: playback pacing, stepping, seeking, speed, layers,
// selection and camera.
#include <gtest/gtest.h>

#include "viewer/ViewerState.h"

namespace stairmap::viewer {
namespace {

/// n scans at 10 Hz starting at UNIX time 1.7e9.
std::vector<double> stamps(int n, double period = 0.1) {
    std::vector<double> s;
    for (int i = 0; i < n; ++i) s.push_back(1.7e9 + period * i);
    return s;
}

TEST(ViewerState, StartsPausedAtNoScan) {
    ViewerState s(stamps(5));
    EXPECT_EQ(s.target(), 0u);
    EXPECT_FALSE(s.playing());
    EXPECT_FALSE(s.tick(100.0));  // paused: time passing changes nothing
    EXPECT_EQ(s.target(), 0u);
}

TEST(ViewerState, PlaysAtTheLogPaceTimesTheSpeed) {
    ViewerState s(stamps(100));
    s.play();
    EXPECT_TRUE(s.tick(50.0));  // the first tick ties the clocks and shows the first scan
    EXPECT_EQ(s.target(), 1u);
    s.tick(50.5);  // 0.5 s of wall time at x1 = 5 more scans (stamps 0.1 .. 0.5)
    EXPECT_EQ(s.target(), 6u);
    s.setSpeedIndex(5);  // x8: re-anchored at the next tick
    s.tick(51.0);
    EXPECT_EQ(s.target(), 6u);
    s.tick(51.25);  // 0.25 s x 8 = 2 s of log = 20 scans
    EXPECT_EQ(s.target(), 26u);
    s.setSpeedIndex(0);  // x0.25
    s.tick(52.0);
    s.tick(54.0);  // 2 s x 0.25 = 0.5 s of log = 5 scans
    EXPECT_EQ(s.target(), 31u);
}

TEST(ViewerState, StopsAtTheEnd) {
    ViewerState s(stamps(10));
    s.play();
    s.tick(0.0);
    s.tick(100.0);
    EXPECT_EQ(s.target(), 10u);
    EXPECT_FALSE(s.playing());
    s.play();  // nothing left to play
    EXPECT_FALSE(s.playing());
}

TEST(ViewerState, StepsAndSeeksWithinTheTimeline) {
    ViewerState s(stamps(4));
    s.stepBack();
    EXPECT_EQ(s.target(), 0u);
    for (int i = 0; i < 6; ++i) s.stepForward();
    EXPECT_EQ(s.target(), 4u);
    s.stepBack();
    EXPECT_EQ(s.target(), 3u);
    s.seek(99);
    EXPECT_EQ(s.target(), 4u);
    s.seek(1);
    EXPECT_EQ(s.target(), 1u);
    s.play();
    s.stepForward();  // stepping pauses
    EXPECT_FALSE(s.playing());
    EXPECT_EQ(s.target(), 2u);
    s.play();
    s.restart();
    EXPECT_EQ(s.target(), 0u);
    EXPECT_FALSE(s.playing());
}

TEST(ViewerState, SpeedIsClampedToTheTable) {
    ViewerState s(stamps(3));
    EXPECT_DOUBLE_EQ(s.speed(), 1.0);
    for (int i = 0; i < 10; ++i) s.faster();
    EXPECT_DOUBLE_EQ(s.speed(), 8.0);
    for (int i = 0; i < 10; ++i) s.slower();
    EXPECT_DOUBLE_EQ(s.speed(), 0.25);
}

TEST(ViewerState, LayersToggleIndependently) {
    ViewerState s(stamps(3));
    const Layer all[] = {Layer::Scan,     Layer::Voxels,    Layer::Submap, Layer::Detector,
                         Layer::Landmarks, Layer::Floors,   Layer::Trajectory};
    for (Layer l : all) EXPECT_TRUE(s.shown(l)) << layerName(l);
    s.toggle(Layer::Detector);
    EXPECT_FALSE(s.layers().detector);
    EXPECT_TRUE(s.layers().scan);
    s.toggle(Layer::Detector);
    EXPECT_TRUE(s.layers().detector);
    s.setShown(Layer::VoxelsRobotFloor, false);
    EXPECT_FALSE(s.layers().voxels_robot_floor);
    Layer parsed;
    EXPECT_TRUE(parseLayer("floor-voxels", parsed));
    EXPECT_EQ(parsed, Layer::VoxelsRobotFloor);
    EXPECT_FALSE(parseLayer("ceiling", parsed));
}

TEST(ViewerState, TabCyclesThroughTheLandmarks) {
    ViewerState s(stamps(3));
    s.selectNext({});
    EXPECT_EQ(s.selected(), -1);
    const std::vector<int> ids = {0, 3, 7};
    s.selectNext(ids);
    EXPECT_EQ(s.selected(), 0);
    s.selectNext(ids);
    EXPECT_EQ(s.selected(), 3);
    s.selectNext(ids);
    EXPECT_EQ(s.selected(), 7);
    s.selectNext(ids);
    EXPECT_EQ(s.selected(), 0);  // wraps
    s.select(5);                 // a landmark that was absorbed meanwhile: the next one after it
    s.selectNext(ids);
    EXPECT_EQ(s.selected(), 7);
}

TEST(ViewerState, CameraCyclesFollowTopOrbit) {
    ViewerState s(stamps(3));
    EXPECT_EQ(s.camera(), viz::CameraMode::Follow);
    s.cycleCamera();
    EXPECT_EQ(s.camera(), viz::CameraMode::Top);
    s.cycleCamera();
    EXPECT_EQ(s.camera(), viz::CameraMode::Orbit);
    s.cycleCamera();
    EXPECT_EQ(s.camera(), viz::CameraMode::Follow);
}

}  // namespace
}  // namespace stairmap::viewer
