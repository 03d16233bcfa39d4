// Replays for the viewer: the same landmarks as a plain mapping run, stepping back equal to
// replaying afresh, the detector's record at hand, and finished map folders.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/config/MapperConfig.h"
#include "io/json/LandmarkJson.h"
#include "io/json/MapperJson.h"
#include "io/rawlog/RawlogScanSource.h"
#include "replay/MapFolder.h"
#include "replay/ReplaySession.h"
#include "replay/ViewFrameBuilder.h"

namespace stairmap::replay {
namespace {

const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/";
const std::string kConfig = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

ReplayOptions twoFloor() {
    ReplayOptions o;
    o.rawlog = kData + "two_floor.rawlog";
    o.poses = kData + "poses.tum";
    o.config = kConfig;
    return o;
}

/// The landmarks of `stairmap map`'s loop: source -> Mapper, no callbacks.
LandmarkMap plainMapping() {
    const pipeline::MapperParams params = io::loadMapperParams(kConfig);
    io::RawlogSourceParams sp;
    sp.sensor_label = params.sensor.label_filter;
    io::RawlogScanSource source(kData + "two_floor.rawlog", sp,
                                io::TumTrajectory::load(kData + "poses.tum"));
    pipeline::Mapper mapper(params);
    while (auto scan = source.next()) mapper.processScan(*scan);
    return mapper.landmarks();
}

void expectSameLandmarks(const std::vector<StaircaseLandmark>& a,
                         const std::vector<StaircaseLandmark>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].id, b[i].id);
        EXPECT_EQ(a[i].observations, b[i].observations);
        EXPECT_EQ(a[i].stairs.steps.size(), b[i].stairs.steps.size());
        EXPECT_EQ(a[i].stairs.location, b[i].stairs.location);
    }
}

TEST(ReplaySession, FullReplayGivesTheSameLandmarksAsMapping) {
    ReplaySession session(twoFloor());
    ASSERT_EQ(session.numScans(), 83u);  // the dataset's scans (datasets/README.md)
    session.seek(session.numScans());
    EXPECT_EQ(session.position(), 83u);
    const LandmarkMap plain = plainMapping();
    ASSERT_EQ(plain.staircases().size(), 2u);  // the two flights of the building
    expectSameLandmarks(session.mapper().landmarks().staircases(), plain.staircases());
    // The latest run's record is at hand for the viewer.
    ASSERT_TRUE(session.lastRun().has_value());
    EXPECT_FALSE(session.lastRun()->debug.candidates.empty());
    EXPECT_GT(session.runs(), 10u);
}

TEST(ReplaySession, SteppingBackEqualsReplayingAfresh) {
    ReplaySession stepped(twoFloor());
    stepped.seek(50);
    stepped.seek(49);  // back: restarts and replays 49 scans
    ReplaySession fresh(twoFloor());
    fresh.seek(49);
    EXPECT_EQ(stepped.position(), 49u);
    EXPECT_EQ(stepped.mapper().stats().scans, fresh.mapper().stats().scans);
    EXPECT_EQ(stepped.lastScan()->index, fresh.lastScan()->index);
    EXPECT_EQ(stepped.runs(), fresh.runs());
    expectSameLandmarks(stepped.mapper().landmarks().staircases(),
                        fresh.mapper().landmarks().staircases());
    stepped.restart();
    EXPECT_EQ(stepped.position(), 0u);
    EXPECT_FALSE(stepped.lastScan().has_value());
    EXPECT_TRUE(stepped.mapper().landmarks().staircases().empty());
}

TEST(ReplaySession, FrameShowsTheCurrentScanAndRun) {
    ReplaySession session(twoFloor());
    session.seek(83);
    const viz::ViewFrame f = frameOf(session, 0);
    ASSERT_NE(f.scan_robot, nullptr);
    EXPECT_EQ(f.scan_robot->size(), session.lastScan()->points_robot.size());
    ASSERT_TRUE(f.T_world_robot.has_value());
    EXPECT_TRUE(f.T_world_robot->isApprox(session.lastScan()->T_world_robot));
    EXPECT_EQ(f.landmarks.size(), 2u);
    EXPECT_EQ(landmarkIds(f), (std::vector<int>{0, 1}));
    ASSERT_TRUE(f.run.has_value());
    EXPECT_NE(f.run->debug, nullptr);
    EXPECT_GT(f.trajectory.size(), 10u);
}

TEST(ReplaySession, BadInputNamesTheFile) {
    ReplayOptions o = twoFloor();
    o.rawlog = "/nonexistent/log.rawlog";
    try {
        ReplaySession s(o);
        FAIL();
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/log.rawlog"), std::string::npos);
    }
    o = twoFloor();
    o.config = "/nonexistent/c.ini";
    EXPECT_ANY_THROW(ReplaySession{o});
}

class MapFolderTest : public testing::Test {
protected:
    void SetUp() override {
        // One folder per test: ctest runs the tests of a fixture in parallel processes.
        dir_ = std::filesystem::path(STAIRMAP_TEST_TMP) / "replay" /
               testing::UnitTest::GetInstance()->current_test_info()->name();
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    std::filesystem::path dir_;
};

TEST_F(MapFolderTest, LoadsWhatMapWrites) {
    ReplaySession session(twoFloor());
    std::ofstream jsonl(dir_ / "detections.jsonl");
    std::size_t records = 0;
    const pipeline::MapperParams params = io::loadMapperParams(kConfig);
    io::RawlogScanSource source(kData + "two_floor.rawlog", {}, io::TumTrajectory::load(kData + "poses.tum"));
    pipeline::Mapper mapper(params);
    mapper.setDetectionCallback([&](const pipeline::DetectionRecord& r) {
        jsonl << io::detectionRecordToJson(r).dump() << "\n";
        ++records;
    });
    while (auto scan = source.next()) mapper.processScan(*scan);
    jsonl.close();
    io::saveLandmarkMapAtomic((dir_ / "landmarks.json").string(), mapper.landmarks());
    mapper.voxelMap().save((dir_ / "map.bt").string());

    ASSERT_TRUE(isMapFolder(dir_.string()));
    const MapFolder folder = loadMapFolder(dir_.string());
    EXPECT_EQ(folder.landmarks.staircases().size(), mapper.landmarks().staircases().size());
    ASSERT_TRUE(folder.voxels.has_value());
    EXPECT_EQ(folder.voxels->numLeaves(), mapper.voxelMap().numLeaves());
    EXPECT_GE(folder.trajectory.size(), 2u);
    EXPECT_LE(folder.trajectory.size(), records);
    ASSERT_TRUE(folder.last_pose.has_value());
}

TEST_F(MapFolderTest, RejectsFoldersWithoutLandmarksAndBadLines) {
    EXPECT_FALSE(isMapFolder(dir_.string()));
    EXPECT_THROW(loadMapFolder(dir_.string()), std::runtime_error);
    io::saveLandmarkMapAtomic((dir_ / "landmarks.json").string(), LandmarkMap{});
    std::ofstream(dir_ / "detections.jsonl") << "{\"robot_pose\": 3}\n";
    try {
        loadMapFolder(dir_.string());
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("detections.jsonl: line 1"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace stairmap::replay
