#include "viewer/ViewerController.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "replay/ViewFrameBuilder.h"

namespace stairmap::viewer {
namespace {

std::vector<double> stampsOf(const replay::ReplaySession& s) { return s.stamps(); }

double sd(const std::vector<double>& v) {
    if (v.size() < 2) return 0.0;
    double mean = 0.0, sq = 0.0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    for (double x : v) sq += (x - mean) * (x - mean);
    return std::sqrt(sq / static_cast<double>(v.size() - 1));
}

std::string format(const char* fmt, double a = 0, double b = 0, double c = 0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, fmt, a, b, c);
    return buf;
}

}  // namespace

ViewerController::ViewerController(std::unique_ptr<replay::ReplaySession> session)
    : session_(std::move(session)), state_(stampsOf(*session_)) {}

ViewerController::ViewerController(replay::MapFolder folder, double robot_height_m)
    : folder_(std::make_unique<replay::MapFolder>(std::move(folder))),
      robot_height_m_(robot_height_m),
      state_({}) {}

bool ViewerController::sync() {
    if (!session_ || session_->position() == state_.target()) return false;
    const auto t0 = std::chrono::steady_clock::now();
    session_->seek(state_.target());
    last_sync_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return true;
}

viz::ViewFrame ViewerController::frame() const {
    return session_ ? replay::frameOf(*session_, state_.selected())
                    : replay::frameOf(*folder_, robot_height_m_, state_.selected());
}

void ViewerController::selectNextLandmark() {
    std::vector<int> ids;
    const auto& landmarks = session_ ? session_->mapper().landmarks().staircases()
                                     : folder_->landmarks.staircases();
    for (const auto& l : landmarks) ids.push_back(l.id);
    std::sort(ids.begin(), ids.end());
    state_.selectNext(ids);
}

int ViewerController::selectAlongRay(const viz::ViewRay& ray) {
    const auto& landmarks = session_ ? session_->mapper().landmarks().staircases()
                                     : folder_->landmarks.staircases();
    state_.select(viz::pickLandmark(landmarks, ray));
    return state_.selected();
}

std::string ViewerController::status() const {
    const auto& landmarks = session_ ? session_->mapper().landmarks().staircases()
                                     : folder_->landmarks.staircases();
    int confirmed = 0;
    for (const auto& l : landmarks) confirmed += l.confirmed ? 1 : 0;
    std::string s;
    if (session_) {
        const std::size_t n = session_->position();
        const auto& stamps = session_->stamps();
        const double t = n > 0 ? stamps[n - 1] - stamps.front() : 0.0;
        const std::size_t pts = session_->lastScan() ? session_->lastScan()->points_robot.size() : 0;
        s = "scan " + std::to_string(n) + "/" + std::to_string(session_->numScans()) +
            format(" | t %.2f s", t) + " | " + std::to_string(pts) + " pts";
        if (session_->lastRun()) s += format(" | detector %.1f ms", session_->lastRun()->detect_ms);
    } else {
        s = "map " + folder_->path;
    }
    s += " | landmarks " + std::to_string(landmarks.size()) + " (" + std::to_string(confirmed) +
         " confirmed)";
    if (session_) s += format(" | x%g ", state_.speed()) + (state_.playing() ? "playing" : "paused");
    return s;
}

StepSpread stepSpread(const Staircase& stairs) {
    std::vector<double> rises, runs, widths;
    const Eigen::Vector2d heading(std::cos(stairs.heading_rad), std::sin(stairs.heading_rad));
    for (std::size_t i = 0; i < stairs.steps.size(); ++i) {
        widths.push_back(stairs.steps[i].length());
        if (i == 0) continue;
        const Eigen::Vector3d d = stairs.steps[i].centre() - stairs.steps[i - 1].centre();
        rises.push_back(std::abs(d.z()));
        runs.push_back(std::abs(heading.dot(d.head<2>())));
    }
    return {sd(rises), sd(runs), sd(widths)};
}

std::vector<std::string> ViewerController::landmarkPanel() const {
    const auto& landmarks = session_ ? session_->mapper().landmarks().staircases()
                                     : folder_->landmarks.staircases();
    for (const auto& l : landmarks) {
        if (l.id != state_.selected()) continue;
        const Staircase& s = l.stairs;
        const StepSpread spread = stepSpread(s);
        return {
            "stair #" + std::to_string(l.id) + (l.confirmed ? " (confirmed)" : " (tentative)"),
            std::string(s.direction == StairDirection::Ascending ? "ascending" : "descending") +
                ", " + std::to_string(s.steps.size()) + " steps" +
                format(", heading %.0f deg", s.heading_rad * 180.0 / M_PI),
            format("rise %.3f +- %.3f m", s.step_height, spread.rise_sd_m),
            format("run %.3f +- %.3f m", s.step_depth, spread.run_sd_m),
            format("width %.2f +- %.2f m", s.step_width, spread.width_sd_m),
            format("slope %.1f deg", s.slope_rad * 180.0 / M_PI),
            "floors " + std::to_string(l.bottom_floor) + " -> " + std::to_string(l.top_floor),
            "observations " + std::to_string(l.observations),
            format("seen %.2f .. %.2f s", l.first_seen_s, l.last_seen_s)};
    }
    return {};
}

}  // namespace stairmap::viewer
