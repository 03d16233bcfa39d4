#pragma once
// SIGUSR1 as a request to write a snapshot of the outputs now (`stairmap live`): while a
// SnapshotSignal object lives, each SIGUSR1 only sets a flag that take() reads and clears, so the
// work happens on the thread that polls it, never in the signal handler. The previous handler comes
// back when the object is destroyed. One object at a time.

namespace stairmap::io {

class SnapshotSignal {
  public:
    SnapshotSignal();
    ~SnapshotSignal();
    SnapshotSignal(const SnapshotSignal&) = delete;
    SnapshotSignal& operator=(const SnapshotSignal&) = delete;

    /// True if SIGUSR1 came since the last call (several signals in between count as one).
    bool take();
};

}  // namespace stairmap::io
