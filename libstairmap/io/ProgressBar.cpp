#include "io/ProgressBar.h"

#include <cstdio>
#include <string>

#include <unistd.h>

namespace stairmap::io {

ProgressBar::ProgressBar(std::ostream& out, bool enabled, std::optional<std::size_t> total)
    : out_(out), enabled_(enabled), total_(total) {}

bool ProgressBar::stderrIsTty() { return ::isatty(STDERR_FILENO) == 1; }

void ProgressBar::update(std::size_t done, double log_time_s) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (drawn_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
    last_draw_ = now;
    drawn_ = true;
    const double wall_s = std::chrono::duration<double>(now - start_).count();
    const double rate = wall_s > 0 ? done / wall_s : 0.0;
    char line[160];
    if (total_ && *total_ > 0 && rate > 0) {
        const double eta_s = (static_cast<double>(*total_) - done) / rate;
        std::snprintf(line, sizeof(line), "\r[%5.1f%%] %zu/%zu scans  %.1f scans/s  ETA %.0f s   ",
                      100.0 * done / *total_, done, *total_, rate, eta_s);
    } else {
        const double rtf = wall_s > 0 ? log_time_s / wall_s : 0.0;
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
