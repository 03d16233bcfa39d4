#pragma once
// A one-line progress display for long replays (scans done, rate, log time, ETA when the log's total
// duration is known), redrawn at most every 0.2 s with '\r'. Disabled instances print nothing.

#include <chrono>
#include <cstddef>
#include <optional>
#include <ostream>

namespace stairmap::io {

class ProgressBar {
public:
    /// total_log_s: duration of the whole log [s] (e.g. the span of its TUM trajectory), for the ETA.
    ProgressBar(std::ostream& out, bool enabled, std::optional<double> total_log_s = std::nullopt);

    /// Call after each scan. log_time_s: log time covered so far [s].
    void update(std::size_t done, double log_time_s);
    /// Clears the line (call before printing anything else, and at the end).
    void finish();

    /// True when stderr is a terminal (the default for showing progress).
    static bool stderrIsTty();

private:
    using Clock = std::chrono::steady_clock;
    std::ostream& out_;
    bool enabled_;
    std::optional<double> total_log_s_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_draw_{};
    bool drawn_ = false;
};

}  // namespace stairmap::io
