#include "io/system/ProgressBar.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace stairmap::io {

ProgressBar::ProgressBar(std::ostream& out, bool enabled, std::optional<double> total_log_s)
    : out_(out), enabled_(enabled), total_log_s_(total_log_s) {}

bool ProgressBar::stderrIsTty() { return ::isatty(STDERR_FILENO) == 1; }

void ProgressBar::update(std::size_t done, double log_time_s) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (drawn_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
    last_draw_ = now;
    drawn_ = true;
    const double wall_s = std::chrono::duration<double>(now - start_).count();
    const double rate = wall_s > 0 ? done / wall_s : 0.0;
    const double rtf = wall_s > 0 ? log_time_s / wall_s : 0.0;
    char line[160];
    if (total_log_s_ && *total_log_s_ > 0 && rtf > 0) {
        // The log advances at `rtf` log seconds per wall second: that gives the time left.
        const double fraction = std::min(1.0, log_time_s / *total_log_s_);
        const double eta_s = std::max(0.0, *total_log_s_ - log_time_s) / rtf;
        std::snprintf(line, sizeof(line),
                      "\r[%5.1f%%] %zu scans  %.1f scans/s  %.1fx real time  ETA %.0f s   ",
                      100.0 * fraction, done, rate, rtf, eta_s);
    } else {
        std::snprintf(line, sizeof(line), "\r%zu scans  %.1f scans/s  log %.1f s  %.1fx real time   ",
                      done, rate, log_time_s, rtf);
    }
    out_ << line << std::flush;
}

void ProgressBar::finish() {
    if (!enabled_ || !drawn_) return;
    out_ << "\r" << std::string(79, ' ') << "\r" << std::flush;
    drawn_ = false;
}

}  // namespace stairmap::io
