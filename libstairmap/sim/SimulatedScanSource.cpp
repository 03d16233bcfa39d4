#include "sim/SimulatedScanSource.h"

#include "sim/ScanSimulator.h"

namespace stairmap::sim {

SimulatedScanSource::SimulatedScanSource(const Scene& scene, const SensorParams& sensor,
                                         const Eigen::Isometry3d& T_robot_sensor,
                                         std::vector<TrajectorySample> samples, unsigned seed,
                                         std::string sensor_label)
    : scene_(scene),
      sensor_(sensor),
      T_robot_sensor_(T_robot_sensor),
      samples_(std::move(samples)),
      rng_(seed),
      label_(std::move(sensor_label)) {
    validate(sensor_);
}

std::optional<Scan> SimulatedScanSource::next() {
    if (next_index_ >= samples_.size()) return std::nullopt;
    const TrajectorySample& sample = samples_[next_index_];
    std::uniform_real_distribution<double> azimuth(0.0, sensor_.horizontal_resolution_deg);
    const auto points_sensor =
        simulateScan(scene_, sample.T_world_robot_true * T_robot_sensor_, sensor_, rng_, azimuth(rng_));
    Scan scan;
    scan.index = next_index_++;
    scan.stamp_s = sample.stamp_s;
    scan.sensor_label = label_;
    scan.T_world_robot = sample.T_world_robot_reported;
    const Eigen::Isometry3f T = T_robot_sensor_.cast<float>();
    scan.points_robot.reserve(points_sensor.size());
    for (const auto& p : points_sensor) scan.points_robot.push_back(T * p);
    return scan;
}

}  // namespace stairmap::sim
