#pragma once
// Ties the viewer's state to its source without any window: a rawlog replay (ReplaySession) or a
// finished map folder. sync() brings the replay to the state's target scan (restarting the replay
// when going back), frame() says what to draw, status() and landmarkPanel() the texts shown.

#include <memory>
#include <string>
#include <vector>

#include "replay/MapFolder.h"
#include "replay/ReplaySession.h"
#include "viewer/ViewerState.h"
#include "viz/ViewPicking.h"
#include "viz/ViewerScene.h"

namespace stairmap::viewer {

class ViewerController {
public:
    /// A rawlog replay (the viewer starts at 0 scans, paused).
    explicit ViewerController(std::unique_ptr<replay::ReplaySession> session);
    /// A finished map folder (no timeline).
    ViewerController(replay::MapFolder folder, double robot_height_m);

    ViewerState& state() { return state_; }
    const ViewerState& state() const { return state_; }
    bool isReplay() const { return session_ != nullptr; }
    const replay::ReplaySession* session() const { return session_.get(); }

    /// Processes scans until the replay matches state().target(); true if it changed.
    bool sync();
    /// What to draw now (selection taken from the state).
    viz::ViewFrame frame() const;
    /// Tab: the next landmark of the current frame.
    void selectNextLandmark();
    /// A click: selects the landmark the ray through the clicked pixel meets first, or clears
    /// the selection when it meets none. Returns the selected id (-1 = none).
    int selectAlongRay(const viz::ViewRay& ray);
    /// "scan 12/83 | t 1.20 s | 28811 pts | detector 1.8 ms | landmarks 2 (1 confirmed) | x1 playing"
    std::string status() const;
    /// Lines about the selected landmark (empty when none): ID, direction, steps, rise/run/width
    /// with their spread over the steps, slope, floors, observations, first/last seen.
    std::vector<std::string> landmarkPanel() const;
    /// Wall time of the last sync() that processed scans [s].
    double lastSyncSeconds() const { return last_sync_s_; }

private:
    std::unique_ptr<replay::ReplaySession> session_;
    std::unique_ptr<replay::MapFolder> folder_;
    double robot_height_m_ = 0.35;
    ViewerState state_;
    double last_sync_s_ = 0.0;
};

/// Mean and standard deviation of the rise, run and width over the steps of a flight [m].
struct StepSpread {
    double rise_sd_m = 0.0, run_sd_m = 0.0, width_sd_m = 0.0;
};
StepSpread stepSpread(const Staircase& stairs);

}  // namespace stairmap::viewer
