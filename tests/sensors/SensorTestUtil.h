#pragma once
// Helpers for the --sensor tests: a sink that keeps what it is given, INI files written next to
// the test's temporary files, and the bundled VLP-16 capture.

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <vector>

#include "live/LiveSource.h"

namespace stairmap::test {

const std::string kRealDir = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/real/";
const std::string kPcap = kRealDir + "sample_velodyne_vlp16_gps.pcap";
const std::string kRawlog = kRealDir + "sample_velodyne_vlp16_gps.rawlog";

/// Keeps every scan pushed, with the time it came (seconds since the sink was made).
class CollectingSink : public live::ScanSink {
public:
    void push(Scan scan) override {
        std::lock_guard<std::mutex> lock(mutex_);
        times_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count());
        scans.push_back(std::move(scan));
    }
    std::vector<Scan> scans;
    std::vector<double> times_s;

private:
    std::mutex mutex_;
    std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

/// A fresh folder for one test's files.
inline std::string tempDir(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "sensors" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

inline std::string writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

/// A rawlog-grabber INI with one CVelodyneScanner section replaying `pcap` once.
inline std::string velodyneIni(const std::string& pcap, bool fast, const std::string& extra = "") {
    return "[global]\nrawlog_prefix = unused\n\n[LIDAR]\ndriver = CVelodyneScanner\nprocess_rate = 1000\n"
           "sensorLabel = lidar\nmodel = VLP16\npcap_input = " + pcap + "\npcap_read_once = true\n"
           "pcap_read_fast = " + std::string(fast ? "true" : "false") + "\n" + extra;
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

/// The first `bytes` bytes of a file, copied to `to`.
inline std::string copyPrefix(const std::string& from, const std::string& to, std::size_t bytes) {
    std::ifstream in(from, std::ios::binary);
    std::string data(bytes, '\0');
    in.read(data.data(), std::streamsize(bytes));
    data.resize(std::size_t(in.gcount()));
    return writeFile(to, data);
}

}  // namespace stairmap::test
