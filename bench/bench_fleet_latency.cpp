// End-to-end latency of the live fleet map on loopback (issue 13): this process publishes the two
// robots' scans of datasets/two_robot_fleet (as `stairmap play --ros2` does, interleaved by stamp,
// at the recorded rate x R) to two `stairmap live --ros2 --robot-name` processes, which feed one
// `stairmap fleet --ros2`; it subscribes to /<fleet>/stairmap/staircases. Every fleet map carries
// the stamp of the scan whose mapping changed a robot's map (live stamps its map with the scan;
// fleet passes the stamp on), so scan published -> fleet map received is measured per update:
// mapping, landmark publication, alignment + fusion, fleet publication and three DDS hops.
// Robot B's stamps are shifted by +0.5 s so that every stamp names one scan.
// Usage: bench_fleet_latency [rate=2]   (options starting with '-' are ignored: `make bench`)
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <dds/dds.h>

#include "StairmapMessages.h"
#include "io/rawlog/RawlogScanSource.h"
#include "io/rawlog/TumTrajectory.h"
#include "ros2/DdsSupport.h"
#include "ros2/Ros2ScanPublisher.h"

namespace {

using namespace stairmap;
using Clock = std::chrono::steady_clock;
const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_robot_fleet/";

double now() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }

pid_t spawn(std::vector<std::string> args) {
    const pid_t pid = fork();
    if (pid != 0) return pid;
    std::vector<char*> argv{const_cast<char*>(STAIRMAP_BIN)};
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(STAIRMAP_BIN, argv.data());
    _exit(127);
}

struct TimedScan {
    int robot = 0;
    Scan scan;
};

/// Both logs (robot-frame points: the preset's sensor pose is the identity), B shifted by 0.5 s.
std::vector<TimedScan> loadScans() {
    std::vector<TimedScan> all;
    for (int r = 0; r < 2; ++r) {
        const std::string log = kData + (r == 0 ? "robot_a" : "robot_b");
        io::RawlogScanSource source(log + ".rawlog", {}, io::TumTrajectory::load(log + "_poses.tum"));
        while (auto scan = source.next()) {
            scan->stamp_s += 0.5 * r;
            all.push_back({r, std::move(*scan)});
        }
    }
    std::stable_sort(all.begin(), all.end(),
                     [](const TimedScan& a, const TimedScan& b) { return a.scan.stamp_s < b.scan.stamp_s; });
    return all;
}

/// Fleet maps received: stamp -> (wall time, confirmed staircases).
struct FleetSample {
    double stamp_s, received_s;
    int confirmed;
};

void takeFleetMaps(dds_entity_t reader, std::vector<FleetSample>& out) {
    void* samples[8] = {nullptr};
    dds_sample_info_t infos[8];
    const dds_return_t n = dds_take(reader, samples, infos, 8, 8);
    for (dds_return_t i = 0; i < n; ++i) {
        if (!infos[i].valid_data) continue;
        const auto& msg = *static_cast<const stairmap_msgs_msg_dds__StaircaseArray_*>(samples[i]);
        int confirmed = 0;
        for (uint32_t k = 0; k < msg.staircases._length; ++k) confirmed += msg.staircases._buffer[k].confirmed;
        out.push_back({msg.header.stamp.sec + 1e-9 * msg.header.stamp.nanosec, now(), confirmed});
    }
    if (n > 0) dds_return_loan(reader, samples, n);
}

}  // namespace

int main(int argc, char** argv) {
    double rate = 2.0;
    for (int i = 1; i < argc; ++i)
        if (argv[i][0] != '-' && std::atof(argv[i]) > 0) rate = std::atof(argv[i]);
    const std::string tag = std::to_string(getpid()), fleet = "bfleet" + tag;
    const std::string config = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";
    const std::string out = "/tmp/bench_fleet_latency_" + tag;
    const std::vector<TimedScan> scans = loadScans();
    std::vector<pid_t> children;
    std::vector<std::unique_ptr<ros2::Ros2ScanPublisher>> publishers;
    for (const char* r : {"a", "b"}) {
        const std::string robot = std::string("b") + r + tag, prefix = "/bfl" + tag + r;
        children.push_back(spawn({"live", "--ros2", "--points-topic", prefix + "/points", "--odom-topic",
                                  prefix + "/odom", "--robot-name", robot, "--config", config, "--out",
                                  out + "/" + r, "--queue", "1000", "--quiet", "--duration", "600"}));
        ros2::Ros2PlayOptions topics;
        topics.points_topic = prefix + "/points";
        topics.odom_topic = prefix + "/odom";
        publishers.push_back(std::make_unique<ros2::Ros2ScanPublisher>(topics));
    }
    children.push_back(spawn({"fleet", "--ros2", "--robot", "ba" + tag, "--robot", "bb" + tag, "--fleet-name",
                              fleet, "--quiet", "--duration", "600"}));
    const ros2::DdsEntity participant = ros2::createParticipant();
    const std::string topic = ros2::ddsTopicName("/stairmap/staircases", fleet);
    const dds_entity_t reader = ros2::createReader(
        participant.get(), ros2::createTopic(participant.get(), &stairmap_msgs_msg_dds__StaircaseArray__desc, topic),
        ros2::Reliability::Reliable, ros2::Durability::TransientLocal, 1000, topic);
    for (const auto& p : publishers) p->waitForSubscribers(30.0, [] { return false; });
    std::this_thread::sleep_for(std::chrono::seconds(1));  // the odometry readers match too

    std::map<double, double> published;  // stamp -> wall time of its publication
    std::vector<FleetSample> maps;
    const double t0 = now(), first = scans.front().scan.stamp_s;
    for (const TimedScan& s : scans) {
        while (now() < t0 + (s.scan.stamp_s - first) / rate) {
            takeFleetMaps(reader, maps);
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        publishers[s.robot]->publish(s.scan, s.scan.points_robot);
        published[s.scan.stamp_s] = now();
    }
    const double end = now() + 5.0;  // the last updates
    while (now() < end) {
        takeFleetMaps(reader, maps);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    for (pid_t c : children) kill(c, SIGINT);
    for (pid_t c : children) waitpid(c, nullptr, 0);
    std::filesystem::remove_all(out);

    std::vector<double> ms;
    double both_ms = -1.0;
    for (const FleetSample& m : maps) {
        const auto p = published.lower_bound(m.stamp_s - 1e-6);  // stamps pass through sec + nanosec
        if (p == published.end() || p->first > m.stamp_s + 1e-6) continue;
        ms.push_back(1e3 * (m.received_s - p->second));
        if (both_ms < 0 && m.confirmed >= 2) both_ms = ms.back();
    }
    std::sort(ms.begin(), ms.end());
    if (ms.empty()) {
        std::printf("no fleet map received\n");
        return 1;
    }
    std::printf("%zu scans at x%.1f, %zu fleet map updates (%zu matched to a scan)\n", scans.size(), rate,
                maps.size(), ms.size());
    std::printf("scan published -> fleet map received [ms]: median %.1f, p95 %.1f, max %.1f\n", ms[ms.size() / 2],
                ms[std::min(ms.size() - 1, ms.size() * 95 / 100)], ms.back());
    std::printf("first fleet map with both staircases confirmed: %.1f ms after its scan\n", both_ms);
    return 0;
}
