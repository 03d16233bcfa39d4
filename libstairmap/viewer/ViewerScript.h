#pragma once
// Viewer actions by name: the window's keys and the test scripts (`stairmap view --script FILE`)
// drive the controller through the same table. A script has one action per line:
//   play | pause | toggle-play | step [N] | back [N] | seek N | restart | faster | slower
//   speed X (0.25 .. 8) | toggle LAYER | show LAYER | hide LAYER | select-next
//   camera follow|top|orbit | camera-next | wait SECONDS | wait-end | quit
// ('#' starts a comment). LAYER: scan voxels floor-voxels submap detector landmarks floors trajectory.

#include <string>
#include <vector>

#include "viewer/ViewerController.h"

namespace stairmap::viewer {

struct ScriptAction {
    std::string verb;
    std::string arg;  ///< "" when the verb takes none
    int line = 0;     ///< 1-based line in the script (0 for key actions)
};

/// Parses a script; throws std::runtime_error "<path>:<line>: <problem>" on a bad line.
std::vector<ScriptAction> loadScript(const std::string& path);
/// Parses one line (no file); throws std::invalid_argument naming the problem.
ScriptAction parseAction(const std::string& text, int line = 0);

/// Applies an action that acts at once (everything except wait, wait-end and quit).
void applyAction(const ScriptAction& action, ViewerController& controller);

/// Runs a script against the clock: actions apply in order; "wait S" holds the next ones for S
/// seconds, "wait-end" until playback stops.
class ScriptRunner {
public:
    explicit ScriptRunner(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}
    /// Applies the actions that are due at `now_s`. Returns false once "quit" was reached or the
    /// script ended (the caller then closes the window).
    bool update(ViewerController& controller, double now_s);

private:
    std::vector<ScriptAction> actions_;
    std::size_t next_ = 0;
    double hold_until_s_ = -1.0;
    bool waiting_end_ = false;
};

}  // namespace stairmap::viewer
