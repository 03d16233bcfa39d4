#pragma once
// The nanogui control panel of the viewer window: playback buttons, timeline slider, speed,
// camera, layer checkboxes, the selected landmark and the status bar. Widgets call the
// controller; update() copies the controller's state back into the widgets once per frame.

#include <array>
#include <vector>

#include "viewer/ViewerController.h"

namespace mrpt::gui {
class CDisplayWindowGUI;
}
namespace nanogui {
class Button;
class CheckBox;
class Label;
class Slider;
class Widget;
}

namespace stairmap::viewer {

class ViewerPanel {
public:
    ViewerPanel(mrpt::gui::CDisplayWindowGUI& win, ViewerController& controller);
    void update();

private:
    void addPlayback(nanogui::Widget* w);
    void addLayers(nanogui::Widget* w);
    void addLandmarkPanel(nanogui::Widget* w);

    ViewerController& c_;
    nanogui::Button* play_ = nullptr;
    nanogui::Slider* timeline_ = nullptr;
    nanogui::Label* speed_ = nullptr;
    nanogui::Label* camera_ = nullptr;
    nanogui::Label* status_ = nullptr;
    std::array<nanogui::CheckBox*, 8> layers_{};
    std::vector<nanogui::Label*> landmark_lines_;
};

}  // namespace stairmap::viewer
