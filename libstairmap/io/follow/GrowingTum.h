#pragma once
// A TUM trajectory file that another program is still writing ("t x y z qx qy qz qw" lines, '#'
// comments): each refresh() reads the lines completed since the last one. A last line without its
// newline is left for the next refresh (writers flush in the middle of lines). Never blocks: a
// sensor source polls it (sensors/PoseWait); GrowingTrajectory adds the waiting a lossless
// follower needs.

#include <cstdint>
#include <string>

#include "io/rawlog/TumTrajectory.h"

namespace stairmap::io {

class GrowingTum {
public:
    /// The file must exist (it may be empty). Throws std::runtime_error "<path>: no such file".
    explicit GrowingTum(std::string path);

    /// Reads newly completed lines; returns true if poses were added. Throws std::runtime_error
    /// "<path>:<line>: <problem>" for a malformed line or a time that does not increase, and
    /// "<path>: ..." if the file vanished or shrank (rewritten instead of appended to).
    bool refresh();

    /// Forgets poses before `t` (keeping the last one before it, for interpolation), so a long run
    /// holds a bounded window. Cost: amortised O(1) per pose (the copy happens once at least half
    /// of the poses can go).
    void forgetBefore(double t);

    const TumTrajectory& trajectory() const { return trajectory_; }
    /// Poses read since the start (forgotten ones included).
    std::size_t posesRead() const { return poses_read_; }
    const std::string& path() const { return path_; }

private:
    void parseLine(const std::string& line);
    std::string path_;
    std::uint64_t offset_ = 0;     // [bytes] consumed so far (complete lines only)
    std::size_t line_number_ = 0;  // of the last consumed line
    TumTrajectory trajectory_;
    std::size_t poses_read_ = 0;
};

}  // namespace stairmap::io
