#include "sensors/SensorSource.h"

#include <mrpt/core/Clock.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "io/rawlog/PoseConversion.h"
#include "io/follow/GrowingTum.h"
#include "io/rawlog/MrptErrorText.h"
#include "sensors/SensorDriver.h"

namespace stairmap::sensors {
namespace {

using Clock = std::chrono::steady_clock;

double wallClockNow() { return mrpt::Clock::toDouble(mrpt::Clock::now()); }

/// Sleeps `seconds` in slices of at most 50 ms, returning early once `halt` is set.
void sleepUnlessHalted(double seconds, const std::atomic<bool>& halt) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (!halt && Clock::now() < end) {
        const auto left = std::chrono::duration<double>(end - Clock::now()).count();
        std::this_thread::sleep_for(std::chrono::duration<double>(std::min(left, 0.05)));
    }
}

/// Thread-safe named counters (LiveSource::counters()).
class Counters {
public:
    void add(const std::string& key, std::size_t n = 1) {
        std::lock_guard<std::mutex> lock(mutex_);
        values_[key] += n;
    }
    void set(const std::string& key, std::size_t n) {
        std::lock_guard<std::mutex> lock(mutex_);
        values_[key] = n;
    }
    std::map<std::string, std::size_t> snapshot() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return values_;
    }

private:
    mutable std::mutex mutex_;
    std::map<std::string, std::size_t> values_;
};

class SensorSource final : public live::LiveSource {
public:
    SensorSource(const std::string& ini_path, const SensorSourceOptions& options);
    void run(live::ScanSink& sink, const std::atomic<bool>& stop) override;
    bool lossy() const override { return true; }
    std::string describe() const override;
    std::map<std::string, std::size_t> counters() const override { return counters_.snapshot(); }

private:
    void driverLoop(SensorDriver& driver);
    void handleObservation(mrpt::obs::CObservation& obs, const SensorDriver& driver);
    bool deliver(live::ScanSink& sink);  // true while anything is still to come
    void joinDrivers(std::vector<std::thread>& threads);

    std::string ini_path_;
    SensorSourceOptions options_;
    std::vector<std::unique_ptr<SensorDriver>> drivers_;
    std::optional<io::GrowingTum> poses_;
    PoseWait waiting_;
    Counters counters_;

    std::mutex inbox_mutex_;  // guards inbox_, errors_
    std::condition_variable inbox_cv_;
    std::deque<std::pair<Scan, double>> inbox_;  // decoded scans and their arrival [s, steady]
    std::vector<std::string> errors_;            // fatal driver-thread errors
    std::atomic<bool> halt_{false};              // drivers stop
    std::atomic<std::size_t> running_{0};        // driver threads still producing
    std::atomic<std::size_t> next_index_{0};
    Clock::time_point t0_ = Clock::now();
};

SensorSource::SensorSource(const std::string& ini_path, const SensorSourceOptions& options)
    : ini_path_(ini_path), options_(options), waiting_(options.pose_wait) {
    if (options_.static_robot == !options_.poses_path.empty()) {
        throw std::invalid_argument("--sensor needs exactly one of --poses FILE.tum and --static-robot");
    }
    for (const DriverSection& section : readDriverSections(ini_path)) {
        if (options_.T_robot_sensor && section.has_pose_keys) {
            throw std::runtime_error(section.identity() + ": sets pose_x .. pose_roll while the stairmap config's "
                                     "[sensor] pose_*_m/_deg set the sensor pose too; keep one");
        }
        drivers_.push_back(std::make_unique<SensorDriver>(section));
        const auto& pcap = drivers_.back()->pcap();
        if (pcap && pcap->truncated) counters_.add("pcap_truncated_files");
    }
    if (!options_.poses_path.empty()) {
        poses_.emplace(options_.poses_path);
        poses_->refresh();  // a malformed pose file fails here, before any output is touched
    }
    for (const char* key : {"observations", "scans", "scans_pushed", "scans_without_pose", "bad_observations",
                            "other_observations", "points_pushed", "driver_errors", "dropped_scans",
                            "skipped_label"}) {
        counters_.add(key, 0);
    }
}

std::string SensorSource::describe() const {
    std::string d = "MRPT sensors " + ini_path_ + ":";
    for (const auto& driver : drivers_) d += " " + driver->describe();
    return d + (options_.static_robot ? ", static robot" : ", poses " + options_.poses_path);
}

void SensorSource::handleObservation(mrpt::obs::CObservation& obs, const SensorDriver& driver) {
    counters_.add("observations");
    if (!io::isConvertible3DObservation(obs)) {
        counters_.add("other_observations");  // e.g. the Velodyne's GPS packets
        return;
    }
    const std::string& wanted = options_.sensor_label;
    if (!wanted.empty() && obs.sensorLabel != wanted && obs.sensorLabel != wanted + "_SCAN") {
        counters_.add("skipped_label");
        return;
    }
    counters_.add("scans");
    if (options_.T_robot_sensor) obs.setSensorPose(io::toCPose3D(*options_.T_robot_sensor));
    io::ObservationPoints points;
    try {
        points = io::observationToRobotPoints(obs, options_.conversion);
    } catch (const std::exception&) {
        points.convertible = false;
    }
    if (!points.convertible || points.points_robot.empty()) {
        counters_.add("bad_observations");  // undecodable, or not one valid return
        return;
    }
    Scan scan;
    scan.index = next_index_++;
    scan.sensor_label = obs.sensorLabel.empty() ? driver.section().section : obs.sensorLabel;
    scan.stamp_s = options_.stamps == SensorSourceOptions::Stamps::Arrival || obs.timestamp == INVALID_TIMESTAMP
                       ? wallClockNow()
                       : mrpt::Clock::toDouble(obs.timestamp);
    scan.points_robot = std::move(points.points_robot);
    const double arrival = std::chrono::duration<double>(Clock::now() - t0_).count();
    std::lock_guard<std::mutex> lock(inbox_mutex_);
    inbox_.emplace_back(std::move(scan), arrival);
    while (inbox_.size() > options_.pose_wait.max_pending) {  // the delivering thread stalled
        inbox_.pop_front();
        counters_.add("dropped_scans");
    }
    inbox_cv_.notify_one();
}

void SensorSource::driverLoop(SensorDriver& driver) {
    const double period_s = driver.selfPaced() ? 0.0 : 1.0 / driver.section().process_rate_hz;
    std::vector<mrpt::obs::CObservation::Ptr> observations;
    try {
        for (bool more = true; more && !halt_;) {
            const auto t0 = Clock::now();
            observations.clear();
            const std::size_t errors_before = driver.errors();
            more = driver.step(observations);
            counters_.add("driver_errors", driver.errors() - errors_before);
            for (const auto& obs : observations) handleObservation(*obs, driver);
            sleepUnlessHalted(period_s - std::chrono::duration<double>(Clock::now() - t0).count(), halt_);
        }
    } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(inbox_mutex_);
        errors_.push_back(driver.section().identity() + ": " + driver.section().driver + " failed: " + io::mrptErrorText(e));
    }
    --running_;
    inbox_cv_.notify_one();
}

bool SensorSource::deliver(live::ScanSink& sink) {
    std::deque<std::pair<Scan, double>> arrived;
    {
        std::unique_lock<std::mutex> lock(inbox_mutex_);
        inbox_cv_.wait_for(lock, std::chrono::duration<double>(options_.poll_period_s),
                           [this] { return !inbox_.empty() || !errors_.empty(); });
        if (!errors_.empty()) throw std::runtime_error(errors_.front());
        arrived.swap(inbox_);
    }
    std::vector<Scan> ready;
    if (options_.static_robot) {
        for (auto& [scan, arrival] : arrived) ready.push_back(std::move(scan));  // identity pose
    } else {
        for (auto& [scan, arrival] : arrived) waiting_.add(std::move(scan), arrival);
        poses_->refresh();
        ready = waiting_.release(poses_->trajectory(), std::chrono::duration<double>(Clock::now() - t0_).count());
        counters_.set("scans_without_pose", waiting_.withoutPose());
        if (!ready.empty()) poses_->forgetBefore(ready.back().stamp_s - options_.keep_poses_s);
    }
    for (Scan& scan : ready) {
        counters_.add("scans_pushed");
        counters_.add("points_pushed", scan.points_robot.size());
        sink.push(std::move(scan));
    }
    std::lock_guard<std::mutex> lock(inbox_mutex_);
    return running_ > 0 || !inbox_.empty() || waiting_.pending() > 0;
}

void SensorSource::joinDrivers(std::vector<std::thread>& threads) {
    halt_ = true;
    for (auto& t : threads) {
        if (t.joinable()) t.join();
    }
}

void SensorSource::run(live::ScanSink& sink, const std::atomic<bool>& stop) {
    t0_ = Clock::now();
    halt_ = false;
    running_ = drivers_.size();
    std::vector<std::thread> threads;
    for (auto& driver : drivers_) threads.emplace_back([this, &driver] { driverLoop(*driver); });
    try {
        while (!stop && deliver(sink)) {
        }
    } catch (...) {
        joinDrivers(threads);
        throw;
    }
    joinDrivers(threads);
}

}  // namespace

std::optional<Eigen::Isometry3d> sensorPoseOnRobot(const pipeline::SensorParams& s) {
    if (s.pose_x_m == 0 && s.pose_y_m == 0 && s.pose_z_m == 0 && s.pose_yaw_deg == 0 && s.pose_pitch_deg == 0 &&
        s.pose_roll_deg == 0) {
        return std::nullopt;
    }
    const double d2r = M_PI / 180.0;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = (Eigen::AngleAxisd(s.pose_yaw_deg * d2r, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(s.pose_pitch_deg * d2r, Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(s.pose_roll_deg * d2r, Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    T.translation() = Eigen::Vector3d(s.pose_x_m, s.pose_y_m, s.pose_z_m);
    return T;
}

std::unique_ptr<live::LiveSource> makeSensorSource(const std::string& ini_path,
                                                   const SensorSourceOptions& options) {
    return std::make_unique<SensorSource>(ini_path, options);
}

}  // namespace stairmap::sensors
