#pragma once
// The simulator as a ScanSource: scans are cast on demand along a trajectory, so tests and the
// mapper can run on a scene without writing a rawlog first.

#include <optional>
#include <random>
#include <vector>

#include "core/Scan.h"
#include "sim/Scene.h"
#include "sim/SensorModel.h"
#include "sim/Trajectory.h"

namespace stairmap::sim {

class SimulatedScanSource : public ScanSource {
public:
    /// `scene` must outlive the source. Scans carry the REPORTED pose (with drift) as
    /// T_world_robot and points in the robot frame (T_robot_sensor applied); the true poses are in
    /// samples(). Noise is drawn from `seed`.
    SimulatedScanSource(const Scene& scene, const SensorParams& sensor,
                        const Eigen::Isometry3d& T_robot_sensor,
                        std::vector<TrajectorySample> samples, unsigned seed,
                        std::string sensor_label = "lidar");

    std::optional<Scan> next() override;

    const std::vector<TrajectorySample>& samples() const { return samples_; }

private:
    const Scene& scene_;
    SensorParams sensor_;
    Eigen::Isometry3d T_robot_sensor_;
    std::vector<TrajectorySample> samples_;
    std::mt19937 rng_;
    std::string label_;
    std::size_t next_index_ = 0;
};

}  // namespace stairmap::sim
