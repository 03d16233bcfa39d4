// The issue 13 CI test: five processes on loopback. Two robots, each `stairmap play --ros2` (its log
// of datasets/two_robot_fleet) + `stairmap live --ros2 --robot-name`, and `stairmap fleet --ros2`.
// Robot B reports poses in its own frame (the scene's odom_frame, gt.json T_world_odom). B plays
// first; robot A starts once B has mapped a flight. When B's map holds both flights, B's live
// process is killed (SIGKILL) while A is still playing. The fleet must keep B's landmarks, recover
// B's frame (5 cm, 1 deg against gt.json) and end with one confirmed landmark per staircase of
// gt.json, on its nosings, fed by both robots. Each process is bounded (--duration, waits that kill).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "StairmapMessages.h"
#include "apps/ChildProcess.h"
#include "ros2/LandmarkMessages.h"
#include "ros2/TestSubscriber.h"

namespace stairmap::ros2 {
namespace {

using namespace std::chrono_literals;
using nlohmann::json;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_robot_fleet/";
const std::string kConfig = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

/// The latest StaircaseArray of one namespace (reliable, transient-local: a late reader gets it).
class MapWatch {
public:
    explicit MapWatch(const std::string& ns)
        : sub_(&stairmap_msgs_msg_dds__StaircaseArray__desc, ddsTopicName("/stairmap/staircases", ns),
               Reliability::Reliable, Durability::TransientLocal) {}
    /// Takes samples until done() (true) or the timeout (false).
    bool waitFor(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
        return sub_.receive([this](const void* s) { take(s); }, done, timeout);
    }
    /// Takes samples until none came for `quiet` (at most `timeout`).
    bool waitQuiet(std::chrono::milliseconds quiet, std::chrono::milliseconds timeout) {
        last_ = Clock::now();
        return waitFor([&] { return Clock::now() - last_ > quiet; }, timeout);
    }
    int confirmed() const {
        int n = 0;
        for (const auto& l : latest_.staircases) n += l.confirmed;
        return n;
    }
    const LandmarkMapState& latest() const { return latest_; }
    double stamp() const { return stamp_; }

private:
    void take(const void* s) {
        const auto& msg = *static_cast<const stairmap_msgs_msg_dds__StaircaseArray_*>(s);
        latest_ = landmarkState(msg);
        stamp_ = msg.header.stamp.sec + 1e-9 * msg.header.stamp.nanosec;
        last_ = Clock::now();
    }
    test::TestSubscriber sub_;
    LandmarkMapState latest_;
    double stamp_ = -1.0;
    Clock::time_point last_ = Clock::now();
};

struct FleetRun {
    std::string tag = std::to_string(getpid());
    fs::path dir = fs::path(STAIRMAP_TEST_TMP) / ("ros2_fleet_loop_" + tag);
    std::string robot(char r) const { return std::string("fl") + r + tag; }
    std::string topic(char r, const char* what) const { return "/flt" + tag + r + "/" + what; }
    test::ChildOptions child(const std::string& name) const {
        test::ChildOptions c;
        c.stderr_path = (dir / (name + ".err")).string();
        return c;
    }
    pid_t live(char r) const {
        return test::spawnStairmap({"live", "--ros2", "--points-topic", topic(r, "points"), "--odom-topic",
                                    topic(r, "odom"), "--robot-name", robot(r), "--config", kConfig, "--out",
                                    (dir / robot(r)).string(), "--queue", "1000", "--duration", "300"},
                                   child(std::string("live_") + r));
    }
    // B at x4, A at x1 and later: A's last flight (from its scan 20 of 29) comes well after B's log ended
    pid_t play(char r, const char* rate) const {
        const std::string log = kData + "robot_" + r;
        return test::spawnStairmap({"play", log + ".rawlog", "--poses", log + "_poses.tum", "--config", kConfig,
                                    "--ros2", "--rate", rate, "--points-topic", topic(r, "points"),
                                    "--odom-topic", topic(r, "odom"), "--wait-subscribers", "30"},
                                   child(std::string("play_") + r));
    }
    pid_t fleet() const {
        return test::spawnStairmap({"fleet", "--ros2", "--robot", robot('a'), "--robot", robot('b'), "--fleet-name",
                                    "fleet" + tag, "--out", (dir / "fleet").string(), "--duration", "300"},
                                   child("fleet"));
    }
    std::string err(const std::string& name) const { return test::fileText((dir / (name + ".err")).string()); }
};

/// Own DDS domain per test process (parallel ctest runs stay apart) and the loopback file; the
/// children inherit both.
void isolateDds() {
    const std::string domain = std::to_string(100 + getpid() % 120);
    setenv("ROS_DOMAIN_ID", domain.c_str(), 1);
    const std::string uri = std::string("file://") + STAIRMAP_SOURCE_DIR + "/config/cyclonedds_loopback.xml";
    setenv("CYCLONEDDS_URI", uri.c_str(), 1);
}

/// gt.json robots[].T_world_odom (absent: the robot reports world poses).
Eigen::Isometry3d odomFrame(const json& robot) {
    if (!robot.contains("T_world_odom")) return Eigen::Isometry3d::Identity();
    const json& rows = robot["T_world_odom"];
    Eigen::Matrix4d m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m(r, c) = rows.at(r).at(c).get<double>();
    return Eigen::Isometry3d(m);
}

json readJson(const fs::path& p) { return json::parse(test::fileText(p.string())); }

/// Distance from p to the segment a-b.
double toSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return (p - (a + t * (b - a))).norm();
}

/// Every step of `l` (both ends' midpoint) lies on a nosing of the gt staircase `gt` (in the
/// fleet frame): within 10 cm of a nosing segment.
bool onNosings(const StaircaseLandmark& l, const json& gt, const Eigen::Isometry3d& T_fleet_world) {
    for (const StairEdge& e : l.stairs.steps) {
        double best = 1e9;
        for (const json& n : gt["nosings"]) {
            const Eigen::Vector3d a(n["start"][0], n["start"][1], n["start"][2]);
            const Eigen::Vector3d b(n["end"][0], n["end"][1], n["end"][2]);
            best = std::min(best, toSegment(0.5 * (e.start + e.end), T_fleet_world * a, T_fleet_world * b));
        }
        if (best > 0.10) return false;
    }
    return !l.stairs.steps.empty();
}

/// The fleet's landmarks against gt.json: each gt staircase has exactly one confirmed landmark on
/// its nosings with its rise and run, and no confirmed landmark is elsewhere.
void expectOnePerStaircase(const LandmarkMapState& fleet, const json& gt, const Eigen::Isometry3d& T_fleet_world) {
    std::set<int> matched;
    for (const json& s : gt["staircases"]) {
        int hits = 0;
        for (const auto& l : fleet.staircases) {
            if (!l.confirmed || !onNosings(l, s, T_fleet_world)) continue;
            ++hits;
            matched.insert(l.id);
            EXPECT_NEAR(l.stairs.step_height, s["rise_m"].get<double>(), 0.02) << s["name"];
            EXPECT_NEAR(l.stairs.step_depth, s["run_m"].get<double>(), 0.03) << s["name"];
        }
        EXPECT_EQ(hits, 1) << s["name"];
    }
    for (const auto& l : fleet.staircases) EXPECT_TRUE(!l.confirmed || matched.count(l.id)) << "landmark " << l.id;
}

/// alignment.json: robot B's frame in the fleet (robot A's) frame against gt.json, 5 cm and 1 deg.
void expectBAligned(const json& alignment, const std::string& b, const Eigen::Isometry3d& T_a_b) {
    ASSERT_EQ(alignment["maps"].size(), 2u) << alignment.dump();
    const json& m = alignment["maps"][1];
    EXPECT_EQ(m["source"], b);
    const json& T = m["T_first_this"];
    const double dx = T["x"].get<double>() - T_a_b.translation().x();
    const double dy = T["y"].get<double>() - T_a_b.translation().y();
    const double dz = T["z"].get<double>() - T_a_b.translation().z();
    const double yaw = std::atan2(T_a_b.linear()(1, 0), T_a_b.linear()(0, 0)) * 180 / M_PI;
    const double dyaw = std::remainder(T["yaw_deg"].get<double>() - yaw, 360.0);
    std::printf("[ fleet    ] robot B's frame recovered live: error xy %.1f cm, z %.1f cm, yaw %.2f deg "
                "(%zu shared staircases)\n", 100 * std::hypot(dx, dy), 100 * std::abs(dz), dyaw, m["pairs"].size());
    EXPECT_LT(std::hypot(dx, dy), 0.05);
    EXPECT_LT(std::abs(dz), 0.05);
    EXPECT_LT(std::abs(dyaw), 1.0);
}

/// landmarks.json and provenance.json of the fleet: the confirmed landmarks are those published,
/// and each was fed by both robots (robot 0 = A, robot 1 = B).
void expectFedByBoth(const fs::path& out, const LandmarkMapState& published) {
    std::set<int> confirmed, published_confirmed;
    const json landmarks = readJson(out / "landmarks.json");
    for (const json& l : landmarks["staircases"])
        if (l["confirmed"].get<bool>()) confirmed.insert(l["id"].get<int>());
    for (const auto& l : published.staircases)
        if (l.confirmed) published_confirmed.insert(l.id);
    EXPECT_EQ(confirmed, published_confirmed);
    const json prov = readJson(out / "provenance.json");
    int checked = 0;
    for (const json& l : prov["staircases"]) {
        if (!confirmed.count(l["id"].get<int>())) continue;
        std::set<int> robots;
        for (const json& c : l["sources"]) robots.insert(c["map"].get<int>());
        EXPECT_TRUE(robots.count(0) && robots.count(1)) << l.dump();
        ++checked;
    }
    EXPECT_EQ(checked, static_cast<int>(confirmed.size())) << prov.dump();
}

/// Every child of the test; one still running when the test ends (a failed ASSERT) is killed.
class Children {
public:
    pid_t add(pid_t pid) {
        pids_.push_back(pid);
        return pid;
    }
    int wait(pid_t pid, std::chrono::milliseconds timeout) {
        reaped_.insert(pid);
        return test::waitForExit(pid, timeout);
    }
    /// Still running (not reaped, not exited): waitid without reaping.
    static bool running(pid_t pid) {
        siginfo_t info{};
        return ::waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == 0;
    }
    ~Children() {
        for (pid_t p : pids_) {
            if (reaped_.count(p)) continue;
            ::kill(p, SIGKILL);
            ::waitpid(p, nullptr, 0);
        }
    }

private:
    std::vector<pid_t> pids_;
    std::set<pid_t> reaped_;
};

/// The fleet's outputs against gt.json: landmarks (published), robot B's frame, provenance.
void checkFleetOutputs(const FleetRun& run, const LandmarkMapState& published) {
    const json gt = readJson(kData + "gt.json");
    const Eigen::Isometry3d T_world_a = odomFrame(gt["robots"][0]);
    const Eigen::Isometry3d T_world_b = odomFrame(gt["robots"][1]);
    SCOPED_TRACE(run.err("fleet"));
    expectOnePerStaircase(published, gt, T_world_a.inverse());
    expectBAligned(readJson(run.dir / "fleet" / "alignment.json"), run.robot('b'), T_world_a.inverse() * T_world_b);
    expectFedByBoth(run.dir / "fleet", published);
}

TEST(FleetLoopback, TwoRobotsOneKilledFleetKeepsItsLandmarksAndAlignsIt) {
    isolateDds();
    const FleetRun run;
    fs::remove_all(run.dir);
    fs::create_directories(run.dir);
    Children children;
    MapWatch a_map(run.robot('a')), b_map(run.robot('b')), fleet_map("fleet" + run.tag);
    const pid_t fleet = children.add(run.fleet());
    const pid_t live_a = children.add(run.live('a')), live_b = children.add(run.live('b'));
    const pid_t play_b = children.add(run.play('b', "4"));
    ASSERT_TRUE(b_map.waitFor([&] { return b_map.confirmed() >= 1; }, 90s)) << run.err("live_b");
    const pid_t play_a = children.add(run.play('a', "1"));

    // B's log ends; once its map holds both flights and is final, B dies without a word
    EXPECT_EQ(children.wait(play_b, 90s), 0) << run.err("play_b");
    EXPECT_TRUE(b_map.waitFor([&] { return b_map.confirmed() >= 2; }, 30s)) << run.err("live_b");
    b_map.waitQuiet(3s, 30s);
    EXPECT_TRUE(Children::running(play_a)) << "robot A's log ended before B was killed";
    ::kill(live_b, SIGKILL);
    EXPECT_EQ(children.wait(live_b, 20s), 128 + SIGKILL);
    a_map.waitQuiet(100ms, 10s);
    const double a_stamp_at_kill = a_map.stamp();

    EXPECT_EQ(children.wait(play_a, 120s), 0) << run.err("play_a");
    a_map.waitQuiet(3s, 30s);
    ::kill(live_a, SIGINT);
    EXPECT_EQ(children.wait(live_a, 30s), 0) << run.err("live_a");
    // A mapped on after B died, so the fleet rebuilt its map without B's process
    EXPECT_GT(a_map.stamp(), a_stamp_at_kill) << "robot A published nothing after B was killed";
    EXPECT_TRUE(fleet_map.waitFor([&] { return fleet_map.stamp() >= a_map.stamp() - 1e-6; }, 30s))
        << "fleet map of stamp " << fleet_map.stamp() << ", robot A's last " << a_map.stamp();
    ::kill(fleet, SIGINT);
    EXPECT_EQ(children.wait(fleet, 30s), 0) << run.err("fleet");
    checkFleetOutputs(run, fleet_map.latest());
    if (!HasFailure()) fs::remove_all(run.dir);
}

}  // namespace
}  // namespace stairmap::ros2
