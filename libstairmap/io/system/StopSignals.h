#pragma once
// SIGINT and SIGTERM as a request to stop: while a StopSignals object lives, the first such signal
// only records its number (a long run then ends its current step, writes its results and exits
// 128 + signal); a second one ends the process at once (the default action is restored by the
// first). The previous handlers come back when the object is destroyed. One object at a time.

namespace stairmap::io {

class StopSignals {
  public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    /// The signal received (SIGINT or SIGTERM), or 0.
    int received() const;
};

}  // namespace stairmap::io
