#pragma once
// The interactive viewer window: mrpt::gui::CDisplayWindowGUI (GLFW + nanogui) with the 3D scene in
// the background and a control panel (playback, timeline, speed, layers, camera, selected
// landmark, status). Keys: space play/pause, Right/Left step, Up/Down speed, Home restart,
// Tab next landmark, C camera, 1-8 layers, Q/Esc quit. A left click (without dragging) on a
// landmark selects it; a click on empty space clears the selection.

#include <functional>
#include <string>
#include <vector>

#include "viewer/ViewerController.h"
#include "viewer/ViewerScript.h"

namespace stairmap::viewer {

struct WindowOptions {
    std::string title = "stairmap view";
    int width = 1280;   ///< [px]
    int height = 720;   ///< [px]
    std::vector<ScriptAction> script;  ///< run against the clock; the window closes at its end
    bool has_script = false;
    /// Told the selected landmark id (-1 = none) after each click in the scene (may be empty).
    std::function<void(int)> on_click_select;
};

struct WindowStats {
    std::size_t frames = 0;  ///< frames drawn
    double seconds = 0.0;    ///< [s] from the first frame to the close
    double fps() const { return seconds > 0 ? frames / seconds : 0.0; }
};

/// Opens the window and runs until it is closed (or the script ends). Throws std::runtime_error
/// when no window can be opened (no display).
WindowStats runViewerWindow(ViewerController& controller, const WindowOptions& options);

/// The action bound to a GLFW key (verb "" when none).
ScriptAction actionForKey(int glfw_key);

}  // namespace stairmap::viewer
