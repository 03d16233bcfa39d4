#include "viewer/ViewerState.h"

#include <algorithm>

namespace stairmap::viewer {

ViewerState::ViewerState(std::vector<double> stamps) : stamps_(std::move(stamps)) {}

void ViewerState::play() {
    if (target_ >= stamps_.size()) return;  // at the end: nothing to play
    playing_ = true;
    anchored_ = false;  // the next tick ties the log clock to the wall clock
}

void ViewerState::stepForward() {
    pause();
    if (target_ < stamps_.size()) ++target_;
}

void ViewerState::stepBack() {
    pause();
    if (target_ > 0) --target_;
}

void ViewerState::seek(std::size_t n) {
    target_ = std::min(n, stamps_.size());
    anchored_ = false;
    if (target_ >= stamps_.size()) playing_ = false;
}

void ViewerState::restart() {
    pause();
    target_ = 0;
}

bool ViewerState::tick(double now_s) {
    if (!playing_) return false;
    if (!anchored_) {
        // The log clock starts at the stamp of the last processed scan (or the first scan's).
        anchor_wall_s_ = now_s;
        anchor_log_s_ = stamps_[target_ > 0 ? target_ - 1 : 0];
        anchored_ = true;
    }
    const double log_now = anchor_log_s_ + (now_s - anchor_wall_s_) * speed();
    const std::size_t before = target_;
    while (target_ < stamps_.size() && stamps_[target_] <= log_now) ++target_;
    if (target_ >= stamps_.size()) playing_ = false;
    return target_ != before;
}

void ViewerState::setSpeedIndex(int index) {
    speed_index_ = std::clamp(index, 0, kNumSpeeds - 1);
    anchored_ = false;  // re-tie the clocks so the new pace starts from now
}

namespace {
/// The flag of `layer` in `layers` (const or not).
template <class Layers>
auto& flagOf(Layers& layers, Layer layer) {
    switch (layer) {
        case Layer::Scan: return layers.scan;
        case Layer::Voxels: return layers.voxels;
        case Layer::VoxelsRobotFloor: return layers.voxels_robot_floor;
        case Layer::Submap: return layers.submap;
        case Layer::Detector: return layers.detector;
        case Layer::Landmarks: return layers.landmarks;
        case Layer::Floors: return layers.floors;
        case Layer::Trajectory: return layers.trajectory;
    }
    return layers.scan;
}
}  // namespace

bool ViewerState::shown(Layer layer) const { return flagOf(layers_, layer); }

void ViewerState::setShown(Layer layer, bool on) { flagOf(layers_, layer) = on; }

void ViewerState::selectNext(const std::vector<int>& ids) {
    if (ids.empty()) {
        selected_ = -1;
        return;
    }
    const auto next = std::upper_bound(ids.begin(), ids.end(), selected_);
    selected_ = next == ids.end() ? ids.front() : *next;
}

void ViewerState::cycleCamera() {
    camera_ = camera_ == viz::CameraMode::Follow ? viz::CameraMode::Top
              : camera_ == viz::CameraMode::Top  ? viz::CameraMode::Orbit
                                                 : viz::CameraMode::Follow;
}

namespace {
struct LayerName {
    Layer layer;
    const char* name;
};
constexpr LayerName kLayerNames[] = {
    {Layer::Scan, "scan"},           {Layer::Voxels, "voxels"},
    {Layer::VoxelsRobotFloor, "floor-voxels"}, {Layer::Submap, "submap"},
    {Layer::Detector, "detector"},   {Layer::Landmarks, "landmarks"},
    {Layer::Floors, "floors"},       {Layer::Trajectory, "trajectory"}};
}  // namespace

const char* layerName(Layer layer) {
    for (const auto& l : kLayerNames)
        if (l.layer == layer) return l.name;
    return "?";
}

bool parseLayer(const std::string& name, Layer& layer) {
    for (const auto& l : kLayerNames) {
        if (name == l.name) {
            layer = l.layer;
            return true;
        }
    }
    return false;
}

}  // namespace stairmap::viewer
