#pragma once
// A ScanSource that streams an MRPT rawlog (plain or gz) in constant memory, in both formats:
//   #1 actions + sensory frames (CActionCollection, CSensoryFrame, ... ; a frame with no action
//      before it is kept, unlike CRawlog::getActionObservationPairOrObservation), and
//   #2 observations only.
// Every object is read with CArchive::ReadObject, so nothing is silently dropped.
//
// Robot poses, in order of preference:
//   1. a TUM trajectory given to the source, interpolated at the scan time (tum_tolerance_s
//      allowed beyond its ends); when given it is the ONLY pose source;
//   2. CObservationRobotPose entries of the stream, nearest in time within pose_tolerance_s,
//      before or after the scan (see RobotPoseMatcher for the exact rule);
//   3. CActionRobotMovement3D (and 2D) increments composed from the origin (format #1), used only
//      if the stream has no CObservationRobotPose at all.
// A scan with no pose is skipped and counted, never guessed.
// Scan::index is the scan's position among the 3D observations read (after the label filter), so
// skipped scans leave gaps; Scan::stamp_s is the observation timestamp in UNIX seconds.
// Memory: at most RobotPoseMatcherParams::max_pending (16) converted scans are held.
// Observations that are neither 3D scans nor pose carriers are counted by class name and reported
// once per type through the warning handler / messages(). The source never prints.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/io/CStream.h>
#include <mrpt/obs/CObservation.h>

#include "core/Scan.h"
#include "io/rawlog/ObservationToPoints.h"
#include "io/rawlog/TumTrajectory.h"

namespace stairmap::io {

struct RawlogSourceParams {
    std::string sensor_label;        ///< only 3D observations with this label; empty = all
    double pose_tolerance_s = 0.05;  ///< [s] max |t_pose - t_scan| for CObservationRobotPose
    double tum_tolerance_s = 0.05;   ///< [s] allowed extrapolation beyond the TUM time span
    ObservationConversionParams conversion;  ///< Velodyne range limits etc.
    /// [bytes] memory one object may allocate in total while it is deserialized (see
    /// GuardedReadObject.h): a corrupt size field then fails as "corrupt" before the memory is
    /// taken. A scan of 1 M points needs ~16 MB, so 128 MiB leaves room for any real scan and
    /// keeps a damaged file's cost bounded. 0 disables the cap.
    std::uint64_t max_object_bytes = std::uint64_t(128) << 20;
};

struct RawlogSourceStats {
    std::size_t objects_read = 0;       ///< top-level serialized objects read
    std::size_t scans_read = 0;         ///< 3D observations passing the label filter
    std::size_t scans_emitted = 0;      ///< scans returned by next()
    std::size_t skipped_no_pose = 0;    ///< scans dropped because no pose was available
    std::size_t skipped_label = 0;      ///< 3D observations with another sensor label
    std::size_t conversion_failed = 0;  ///< 3D observations whose data could not be converted
    std::size_t robot_poses_read = 0;   ///< CObservationRobotPose entries
    std::size_t odometry_read = 0;      ///< CActionRobotMovement3D/2D increments composed
    std::size_t points_emitted = 0;     ///< points in emitted scans
    std::size_t non_finite_dropped = 0; ///< NaN/Inf points dropped
    std::map<std::string, std::size_t> unsupported;  ///< class name -> count
};

class RawlogScanSource : public ScanSource {
public:
    /// Opens `path` (throws std::runtime_error "<path>: ..." if missing or unreadable).
    /// `trajectory`, if given, is the sole pose source (preference 1 above).
    explicit RawlogScanSource(const std::string& path, const RawlogSourceParams& params = {},
                              std::optional<TumTrajectory> trajectory = std::nullopt);
    /// A pose for a scan time, or std::nullopt (the scan is then skipped and counted).
    using PoseLookup = std::function<std::optional<Eigen::Isometry3d>(double stamp_s)>;
    /// Reads the rawlog from `stream` (plain, uncompressed data; e.g. a growing file whose Read
    /// waits for more bytes); `name` prefixes every message. `poses`, if set, is the sole pose
    /// source (preference 1 above, e.g. a TUM trajectory still being written); it is called once
    /// per scan, on the thread calling next(), and may block.
    RawlogScanSource(std::unique_ptr<mrpt::io::CStream> stream, const std::string& name,
                     const RawlogSourceParams& params, PoseLookup poses);
    ~RawlogScanSource() override;

    /// Next scan (robot-frame points, T_world_robot). std::nullopt at the end. On a truncated or
    /// corrupt file, first returns every good scan before the damage, then throws
    /// std::runtime_error "<path>: truncated or corrupt at object index N (scan index M): ...";
    /// further calls throw the same error.
    std::optional<Scan> next() override;

    const RawlogSourceStats& stats() const { return stats_; }
    /// Warnings so far (one per unsupported type, first pose-less scan, ...), oldest first.
    const std::vector<std::string>& messages() const { return messages_; }
    /// Also called for each warning as it happens (e.g. to print it). Optional.
    void setWarningHandler(std::function<void(const std::string&)> handler);
    const std::string& path() const { return path_; }

private:
    struct Impl;
    void warn(const std::string& message);
    void readOneObject();
    void handleObject(const mrpt::serialization::CSerializable::Ptr& object);
    void handleObservation(const mrpt::obs::CObservation& observation);
    void handleScan(const mrpt::obs::CObservation& observation, double stamp_s);
    void handleActions(const mrpt::obs::CActionCollection& actions);
    void countUnsupported(const std::string& type_name, const std::string& reason);
    void drainMatcher(bool final);
    void noteSkippedNoPose();
    void emit(Scan scan);
    std::string path_;
    RawlogSourceStats stats_;
    std::vector<std::string> messages_;
    std::function<void(const std::string&)> warning_handler_;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stairmap::io
