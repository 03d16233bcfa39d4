// ROS 2 transport latency on loopback: a child process publishes VLP-16-sized clouds (29k points,
// stamped with the wall clock) at 10 Hz with `stairmap play`'s publisher; this process receives
// them with `stairmap live --ros2`'s source (best-effort reader, decoding included) and reports
// the publish -> scan-in-the-sink latency (median, p95, max) and the clouds lost.
// Usage: bench_ros2_latency [clouds=100] [points=29000]   (options starting with '-' are ignored)
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "ros2/Ros2ScanPublisher.h"
#include "ros2/Ros2Source.h"

namespace {

using namespace stairmap;

double wallSeconds() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

struct LatencySink : live::ScanSink {
    void push(Scan scan) override {
        const double now = wallSeconds();
        std::lock_guard<std::mutex> lock(mutex);
        latencies_ms.push_back(1e3 * (now - scan.stamp_s));
    }
    std::mutex mutex;
    std::vector<double> latencies_ms;
};

int publish(const std::string& prefix, int clouds, int points) {
    ros2::Ros2PlayOptions options;
    options.points_topic = prefix + "/points";
    options.odom_topic = prefix + "/odom";
    ros2::Ros2ScanPublisher publisher(options);
    if (publisher.waitForSubscribers(10.0, [] { return false; }) == 0) return 1;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let the odometry reader match too
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-20.0f, 20.0f);
    PointCloud cloud(points);
    for (auto& p : cloud) p = Eigen::Vector3f(u(rng), u(rng), u(rng) / 10.0f);
    for (int k = 0; k < clouds; ++k) {
        Scan scan;
        scan.stamp_s = wallSeconds();
        publisher.publish(scan, cloud);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    publisher.flush(2.0);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // positional numbers only (`make bench` passes --benchmark_* options to every bench_*)
    std::vector<int> numbers;
    for (int i = 1; i < argc; ++i)
        if (argv[i][0] != '-') numbers.push_back(std::atoi(argv[i]));
    const int clouds = numbers.size() > 0 && numbers[0] > 0 ? numbers[0] : 100;
    const int points = numbers.size() > 1 && numbers[1] > 0 ? numbers[1] : 29000;
    const std::string prefix = "/bench_" + std::to_string(getpid());
    const pid_t child = fork();
    if (child == 0) _exit(publish(prefix, clouds, points));

    ros2::Ros2SourceOptions options;
    options.points_topic = prefix + "/points";
    options.odom_topic = prefix + "/odom";
    options.static_robot = true;  // the latency of the clouds alone
    ros2::Ros2Source source(options);
    LatencySink sink;
    std::atomic<bool> stop{false};
    std::thread reader([&] { source.run(sink, stop); });
    int status = 0;
    waitpid(child, &status, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    stop = true;
    reader.join();
    std::vector<double> ms = sink.latencies_ms;
    std::sort(ms.begin(), ms.end());
    if (ms.empty()) {
        std::printf("no cloud received (publisher exit status %d)\n", status);
        return 1;
    }
    std::printf("clouds of %d points: sent %d, received %zu, lost %zu\n", points, clouds, ms.size(),
                std::size_t(clouds) - ms.size());
    std::printf("publish -> scan latency [ms]: median %.2f, p95 %.2f, max %.2f\n", ms[ms.size() / 2],
                ms[std::min(ms.size() - 1, ms.size() * 95 / 100)], ms.back());
    return 0;
}
