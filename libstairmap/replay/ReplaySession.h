#pragma once
// A rawlog replayed scan by scan through the same Mapper as `stairmap map` (same options, same
// results), with the state a viewer draws: the current scan, the latest detector run with its
// debug record. Going back means replaying from the start (mapping runs far faster than real
// time: the bundled two-floor log replays in well under a second).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/DetectorDebug.h"
#include "core/Scan.h"
#include "pipeline/Mapper.h"

namespace stairmap::io {
class RawlogScanSource;
class TumTrajectory;
}

namespace stairmap::replay {

struct ReplayOptions {
    std::string rawlog;  ///< MRPT rawlog (required)
    std::string poses;   ///< TUM trajectory, "" = poses from the rawlog (as `stairmap map`)
    std::string config;  ///< INI file, "" = built-in defaults
    std::string map_in;  ///< landmarks.json to continue, "" = empty map
    bool with_debug = true;  ///< ask the detector for its DetectorDebug record
};

/// The latest detector run, copied out of the mapper's callback (grav frame unless stated).
struct RunSnapshot {
    std::size_t scan_index = 0;
    double stamp_s = 0.0;
    Eigen::Isometry3d T_world_grav = Eigen::Isometry3d::Identity();
    double submap_radius_m = 0.0;
    std::size_t submap_points = 0;
    double detect_ms = 0.0;
    DetectorDebug debug;                            ///< empty unless with_debug
    std::vector<pipeline::DetectionRecord> records;  ///< world frame
};

class ReplaySession {
public:
    /// Loads the config and poses and reads the rawlog once to learn its scans' stamps.
    /// Throws std::runtime_error / std::invalid_argument naming the file on bad input.
    explicit ReplaySession(ReplayOptions options);
    ~ReplaySession();

    std::size_t numScans() const { return stamps_.size(); }
    const std::vector<double>& stamps() const { return stamps_; }  ///< [s] per scan
    std::size_t position() const { return position_; }  ///< scans processed so far
    /// Processes the next scan; false at the end (or at damage, see damage()).
    bool advance();
    /// Brings the session to `n` scans processed (clamped to numScans()); replays from the start
    /// when n < position().
    void seek(std::size_t n);
    void restart();

    const pipeline::Mapper& mapper() const { return *mapper_; }
    const pipeline::MapperParams& params() const { return params_; }
    const std::optional<Scan>& lastScan() const { return last_scan_; }
    /// The latest detector run at or before position(), if any.
    const std::optional<RunSnapshot>& lastRun() const { return last_run_; }
    /// Runs so far (position()), counted from the start.
    std::size_t runs() const { return runs_; }
    /// The error of a truncated / corrupt rawlog ("" if none): scans up to it are replayed.
    const std::string& damage() const { return damage_; }
    const ReplayOptions& options() const { return options_; }

private:
    void open();
    void countScans();
    void onRun(const pipeline::DetectionRun& run);

    ReplayOptions options_;
    pipeline::MapperParams params_;
    std::shared_ptr<const io::TumTrajectory> poses_;
    std::unique_ptr<io::RawlogScanSource> source_;
    std::unique_ptr<pipeline::Mapper> mapper_;
    std::vector<double> stamps_;
    std::size_t position_ = 0;
    std::size_t runs_ = 0;
    std::optional<Scan> last_scan_;
    std::optional<RunSnapshot> last_run_;
    std::string damage_;
};

}  // namespace stairmap::replay
