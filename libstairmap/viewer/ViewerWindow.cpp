#include "viewer/ViewerWindow.h"

// CDisplayWindowGUI first: nanogui sets up the OpenGL headers, then GLFW's key codes come along.
#include <mrpt/gui/CDisplayWindowGUI.h>

#include <mrpt/math/TLine3D.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include "viewer/ViewerPanel.h"
#include "viz/ViewerScene.h"

namespace stairmap::viewer {
namespace {

using Clock = std::chrono::steady_clock;

/// Camera of the window's canvas from a CameraView.
void applyCamera(mrpt::gui::CGlCanvasBase& canvas, const viz::CameraView& v) {
    canvas.setCameraFOV(60.0f);  // as the headless renderer: cameraFor() fits views to 60 deg
    canvas.setCameraPointing(static_cast<float>(v.target.x()), static_cast<float>(v.target.y()),
                             static_cast<float>(v.target.z()));
    canvas.setZoomDistance(static_cast<float>(v.distance_m));
    canvas.setAzimuthDegrees(static_cast<float>(v.azimuth_deg));
    canvas.setElevationDegrees(static_cast<float>(v.elevation_deg));
}

/// The ray through window pixel (x, y) of the view as last drawn: MRPT's viewport keeps the
/// projection of its last render, so the ray matches the picture even while the mouse or the
/// follow camera moves it (a camera read back from the canvas and re-modelled did not, at times).
viz::ViewRay rayOfLastDrawnView(mrpt::gui::CDisplayWindowGUI& win, int x_px, int y_px) {
    mrpt::math::TLine3D line;
    {
        std::lock_guard<std::mutex> lock(win.background_scene_mtx);
        win.background_scene->getViewport("main")->get3DRayForPixelCoord(x_px + 0.5, y_px + 0.5,
                                                                         line);
    }
    viz::ViewRay ray;
    ray.origin = {line.pBase.x, line.pBase.y, line.pBase.z};
    ray.direction = Eigen::Vector3d(line.director.x, line.director.y, line.director.z).normalized();
    return ray;
}

/// The MRPT window, with left clicks on the scene (not on the panel, not a camera drag) reported.
class ClickableWindow : public mrpt::gui::CDisplayWindowGUI {
public:
    using CDisplayWindowGUI::CDisplayWindowGUI;
    std::function<void(int x_px, int y_px)> on_click;

    bool mouseButtonEvent(const nanogui::Vector2i& p, int button, bool down,
                          int modifiers) override {
        constexpr int kClickSlackPx = 4;  // more movement than this between press and release: a drag
        if (button == GLFW_MOUSE_BUTTON_1 && findWidget(p) == this) {
            if (down) {
                press_ = p;
                pressed_ = true;
            } else if (pressed_ && (p - press_).cwiseAbs().maxCoeff() <= kClickSlackPx && on_click) {
                on_click(p.x(), p.y());
            }
        }
        if (!down) pressed_ = false;
        return CDisplayWindowGUI::mouseButtonEvent(p, button, down, modifiers);
    }

private:
    nanogui::Vector2i press_ = nanogui::Vector2i::Zero();
    bool pressed_ = false;
};

/// The loop of one window: script, pacing, replay, scene and panel updates.
class WindowLoop {
public:
    WindowLoop(ViewerController& c, const WindowOptions& o, mrpt::gui::CDisplayWindowGUI& win)
        : c_(c), win_(win), panel_(win, c), script_(o.script), has_script_(o.has_script),
          on_select_(o.on_click_select) {}

    void onFrame() {
        const double now = std::chrono::duration<double>(Clock::now() - t0_).count();
        ++stats_.frames;
        stats_.seconds = now;
        if (has_script_ && !script_.update(c_, now)) nanogui::leave();
        c_.state().tick(now);
        const bool moved = c_.sync();
        if (moved || c_.state().layers() != layers_ || c_.state().selected() != selected_ ||
            c_.state().camera() != camera_ || first_) {
            rebuild(moved);
        }
        panel_.update();
    }

    bool onKey(int key, int action) {
        if (action != GLFW_PRESS && action != GLFW_REPEAT) return false;
        if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) {
            nanogui::leave();
            return true;
        }
        const ScriptAction a = actionForKey(key);
        if (a.verb.empty()) return false;
        applyAction(a, c_);
        return true;
    }

    /// A click at window pixel (x, y): the landmark under it becomes the selection.
    void onClick(int x_px, int y_px) {
        const int id = c_.selectAlongRay(rayOfLastDrawnView(win_, x_px, y_px));
        if (on_select_) on_select_(id);
    }

    const WindowStats& stats() const { return stats_; }

private:
    void rebuild(bool moved) {
        const viz::ViewFrame frame = c_.frame();
        {
            std::lock_guard<std::mutex> lock(win_.background_scene_mtx);
            viz::buildViewerScene(frame, c_.state().layers(), *win_.background_scene);
        }
        const viz::CameraMode mode = c_.state().camera();
        // Follow tracks every new scan; top and orbit are set once and then left to the mouse.
        if (first_ || mode != camera_ || (moved && mode == viz::CameraMode::Follow)) {
            applyCamera(win_.camera(), viz::cameraFor(mode, frame.T_world_robot,
                                                      viz::frameBounds(frame), 225.0));
        }
        camera_ = mode;
        layers_ = c_.state().layers();
        selected_ = c_.state().selected();
        first_ = false;
    }

    ViewerController& c_;
    mrpt::gui::CDisplayWindowGUI& win_;
    ViewerPanel panel_;
    ScriptRunner script_;
    bool has_script_;
    std::function<void(int)> on_select_;
    Clock::time_point t0_ = Clock::now();
    WindowStats stats_;
    viz::ViewLayers layers_;
    int selected_ = -1;
    viz::CameraMode camera_ = viz::CameraMode::Follow;
    bool first_ = true;
};

}  // namespace

ScriptAction actionForKey(int key) {
    static const std::pair<int, const char*> kKeys[] = {
        {GLFW_KEY_SPACE, "toggle-play"}, {GLFW_KEY_RIGHT, "step"},  {GLFW_KEY_LEFT, "back"},
        {GLFW_KEY_UP, "faster"},         {GLFW_KEY_DOWN, "slower"}, {GLFW_KEY_HOME, "restart"},
        {GLFW_KEY_R, "restart"},         {GLFW_KEY_TAB, "select-next"},
        {GLFW_KEY_C, "camera-next"}};
    for (const auto& [k, verb] : kKeys)
        if (k == key) return parseAction(verb);
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_8) {
        static const char* kLayers[] = {"scan",     "voxels",    "floor-voxels", "submap",
                                        "detector", "landmarks", "floors",       "trajectory"};
        return parseAction(std::string("toggle ") + kLayers[key - GLFW_KEY_1]);
    }
    return {};
}

WindowStats runViewerWindow(ViewerController& controller, const WindowOptions& options) {
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr)
        throw std::runtime_error("no display (DISPLAY is not set): use --headless --frames DIR, "
                                 "or run under xvfb-run");
    nanogui::init();
    WindowStats stats;
    {
        mrpt::gui::CDisplayWindowGUI_Params params;
        ClickableWindow win(options.title, options.width, options.height, params);
        win.background_scene = mrpt::opengl::COpenGLScene::Create();
        WindowLoop loop(controller, options, win);
        win.addLoopCallback([&loop] { loop.onFrame(); });
        win.on_click = [&loop](int x, int y) { loop.onClick(x, y); };
        win.addKeyboardCallback([&loop](int key, int, int action, int) { return loop.onKey(key, action); });
        win.performLayout();
        win.drawAll();
        win.setVisible(true);
        nanogui::mainloop(10);  // redraw at least every 10 ms: playback is paced by the loop
        stats = loop.stats();
    }
    nanogui::shutdown();
    return stats;
}

}  // namespace stairmap::viewer
