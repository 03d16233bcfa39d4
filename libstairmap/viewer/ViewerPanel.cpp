#include "viewer/ViewerPanel.h"

#include <mrpt/gui/CDisplayWindowGUI.h>

#include <cmath>

namespace stairmap::viewer {
namespace {

constexpr Layer kPanelLayers[8] = {Layer::Scan,     Layer::Voxels,    Layer::VoxelsRobotFloor,
                                   Layer::Submap,   Layer::Detector,  Layer::Landmarks,
                                   Layer::Floors,   Layer::Trajectory};
constexpr int kLandmarkLines = 9;
constexpr int kPanelWidth = 300;  ///< [px]

nanogui::Widget* row(nanogui::Widget* parent) {
    auto* r = new nanogui::Widget(parent);
    r->setLayout(new nanogui::BoxLayout(nanogui::Orientation::Horizontal,
                                        nanogui::Alignment::Middle, 0, 4));
    return r;
}

nanogui::Button* button(nanogui::Widget* parent, const char* caption, std::function<void()> cb) {
    auto* b = new nanogui::Button(parent, caption);
    b->setCallback(std::move(cb));
    return b;
}

}  // namespace

ViewerPanel::ViewerPanel(mrpt::gui::CDisplayWindowGUI& win, ViewerController& c) : c_(c) {
    nanogui::Window* w = win.createManagedSubWindow("stairmap");
    w->setPosition({8, 8});
    w->setLayout(new nanogui::GroupLayout(8, 4, 8, 10));
    w->setFixedWidth(kPanelWidth);
    addPlayback(w);
    addLayers(w);
    addLandmarkPanel(w);
    nanogui::Window* bar = win.createManagedSubWindow("status");
    bar->setLayout(new nanogui::BoxLayout(nanogui::Orientation::Horizontal,
                                          nanogui::Alignment::Middle, 6, 6));
    status_ = new nanogui::Label(bar, c_.status());
    status_->setFixedWidth(760);
    bar->setPosition({kPanelWidth + 24, 8});
    win.performLayout();
}

void ViewerPanel::addPlayback(nanogui::Widget* w) {
    new nanogui::Label(w, "Playback", "sans-bold");
    auto* r = row(w);
    button(r, "|<", [this] { c_.state().restart(); });
    button(r, "<", [this] { c_.state().stepBack(); });
    play_ = button(r, "Play", [this] { c_.state().togglePlay(); });
    button(r, ">", [this] { c_.state().stepForward(); });
    timeline_ = new nanogui::Slider(w);
    timeline_->setFinalCallback([this](float v) {
        c_.state().seek(static_cast<std::size_t>(std::lround(v * c_.state().numScans())));
    });
    auto* s = row(w);
    button(s, "-", [this] { c_.state().slower(); });
    speed_ = new nanogui::Label(s, "x1");
    button(s, "+", [this] { c_.state().faster(); });
    button(s, "Camera", [this] { c_.state().cycleCamera(); });
    camera_ = new nanogui::Label(s, "follow");
}

void ViewerPanel::addLayers(nanogui::Widget* w) {
    new nanogui::Label(w, "Layers (keys 1-8)", "sans-bold");
    for (int i = 0; i < 8; ++i) {
        const Layer layer = kPanelLayers[i];
        layers_[i] = new nanogui::CheckBox(w, std::to_string(i + 1) + " " + layerName(layer),
                                           [this, layer](bool on) { c_.state().setShown(layer, on); });
    }
}

void ViewerPanel::addLandmarkPanel(nanogui::Widget* w) {
    new nanogui::Label(w, "Selected landmark (Tab)", "sans-bold");
    button(w, "Next landmark", [this] { c_.selectNextLandmark(); });
    for (int i = 0; i < kLandmarkLines; ++i) landmark_lines_.push_back(new nanogui::Label(w, " "));
}

void ViewerPanel::update() {
    const ViewerState& s = c_.state();
    play_->setCaption(s.playing() ? "Pause" : "Play");
    if (s.numScans() > 0) timeline_->setValue(static_cast<float>(s.target()) / s.numScans());
    char speed[16];
    std::snprintf(speed, sizeof speed, "x%g", s.speed());
    speed_->setCaption(speed);
    camera_->setCaption(viz::cameraModeName(s.camera()));
    for (int i = 0; i < 8; ++i) layers_[i]->setChecked(s.shown(kPanelLayers[i]));
    const std::vector<std::string> lines = c_.landmarkPanel();
    for (int i = 0; i < kLandmarkLines; ++i)
        landmark_lines_[i]->setCaption(i < static_cast<int>(lines.size()) ? lines[i]
                                                                          : (i == 0 ? "none" : " "));
    status_->setCaption(c_.status());
}

}  // namespace stairmap::viewer
