#pragma once
// The viewer's state, free of any window: playback over a timeline of scan stamps (play/pause,
// step, seek, restart, speed with real-time pacing), layer switches, the selected landmark and the
// camera mode. The window (ViewerWindow) and the script runner only call these methods, so every
// control is unit-tested without a display.

#include <cstddef>
#include <string>
#include <vector>

#include "viz/ViewerCamera.h"
#include "viz/ViewerScene.h"

namespace stairmap::viewer {

enum class Layer { Scan, Voxels, VoxelsRobotFloor, Submap, Detector, Landmarks, Floors, Trajectory };

/// Playback speeds, slowest first (x0.25 .. x8 of the log's own pace).
constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0, 8.0};
constexpr int kNumSpeeds = 6;
constexpr int kDefaultSpeedIndex = 2;  // x1

class ViewerState {
public:
    /// stamps: [s] of every scan, in order (may be empty: a finished map has no timeline).
    explicit ViewerState(std::vector<double> stamps);

    // --- playback: target() is how many scans should have been processed ---
    std::size_t numScans() const { return stamps_.size(); }
    std::size_t target() const { return target_; }
    bool playing() const { return playing_; }
    void play();
    void pause() { playing_ = false; }
    void togglePlay() { playing_ ? pause() : play(); }
    void stepForward();   ///< one scan; pauses
    void stepBack();      ///< one scan back (the replay restarts and runs up to it); pauses
    void seek(std::size_t n);  ///< clamped to numScans(); keeps playing if it was
    void restart();       ///< back to 0 scans, paused
    /// While playing, moves target() to the last scan whose stamp the log clock has reached:
    /// log time advances speed() times as fast as `now_s` (any monotonic clock [s]). Stops at the
    /// end. Returns true if target() changed.
    bool tick(double now_s);

    double speed() const { return kSpeeds[speed_index_]; }
    int speedIndex() const { return speed_index_; }
    void setSpeedIndex(int index);  ///< clamped to the table
    void faster() { setSpeedIndex(speed_index_ + 1); }
    void slower() { setSpeedIndex(speed_index_ - 1); }

    // --- layers ---
    const viz::ViewLayers& layers() const { return layers_; }
    bool shown(Layer layer) const;
    void setShown(Layer layer, bool on);
    void toggle(Layer layer) { setShown(layer, !shown(layer)); }

    // --- landmark selection (Tab) ---
    int selected() const { return selected_; }  ///< landmark id, -1 = none
    void select(int id) { selected_ = id; }
    /// The next of `ids` (ascending) after the current selection, wrapping; -1 if ids is empty.
    void selectNext(const std::vector<int>& ids);

    // --- camera ---
    viz::CameraMode camera() const { return camera_; }
    void setCamera(viz::CameraMode mode) { camera_ = mode; }
    void cycleCamera();

private:
    std::vector<double> stamps_;
    std::size_t target_ = 0;
    bool playing_ = false;
    bool anchored_ = false;  ///< the log clock is tied to the wall clock (set by tick)
    double anchor_wall_s_ = 0.0, anchor_log_s_ = 0.0;
    int speed_index_ = kDefaultSpeedIndex;
    viz::ViewLayers layers_;
    int selected_ = -1;
    viz::CameraMode camera_ = viz::CameraMode::Follow;
};

/// "scan", "voxels", "floor-voxels", "submap", "detector", "landmarks", "floors", "trajectory".
const char* layerName(Layer layer);
bool parseLayer(const std::string& name, Layer& layer);

}  // namespace stairmap::viewer
