#pragma once
// A TUM trajectory file that is still being written (e.g. by a SLAM system running beside the
// recorder). New complete lines are read as they appear; a line without its '\n' yet waits.
// poseAt(t) waits (bounded) until the file holds a pose at or after t, so a scan gets the same
// interpolated pose as `stairmap map` would get from the finished file; if the file stops growing
// for wait_s first, the poses there are used (within tolerance_s of their ends, else none).
// Memory: poses older than keep_s before the latest query are forgotten (queries come in time
// order), so a long run keeps a bounded window. The file is read by GrowingTum; this class adds
// the waiting.

#include <Eigen/Geometry>
#include <atomic>
#include <chrono>
#include <optional>
#include <string>

#include "io/follow/GrowingTum.h"

namespace stairmap::io {

struct GrowingTrajectoryParams {
    double tolerance_s = 0.05;    ///< [s] extrapolation allowed beyond the poses' ends (as map)
    double wait_s = 5.0;          ///< [s] a query waits while the file grows; gives up after
                                  ///< this long without growth
    double poll_period_s = 0.05;  ///< [s] checks for growth and the stop flag
    double keep_s = 30.0;         ///< [s] poses kept before the latest query time
};

class GrowingTrajectory {
public:
    /// Throws std::runtime_error "<path>: ..." if the file cannot be opened.
    GrowingTrajectory(const std::string& path, const GrowingTrajectoryParams& params,
                      const std::atomic<bool>& stop);

    /// The pose at `t` (see above); std::nullopt when the file has none for t. Throws
    /// std::runtime_error naming the file and line on a malformed line. Queries in time order.
    std::optional<Eigen::Isometry3d> poseAt(double t);

    std::size_t posesRead() const { return tum_.posesRead(); }
    std::size_t posesKept() const { return tum_.trajectory().size(); }
    /// Queries that had to wait for the file to grow.
    std::size_t waits() const { return waits_; }

private:
    GrowingTum tum_;
    GrowingTrajectoryParams params_;
    const std::atomic<bool>& stop_;
    std::size_t waits_ = 0;
    std::chrono::steady_clock::time_point last_growth_;
};

}  // namespace stairmap::io
