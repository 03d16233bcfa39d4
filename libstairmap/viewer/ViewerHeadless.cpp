#include "viewer/ViewerHeadless.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "viz/HeadlessRenderer.h"
#include "viz/ViewerScene.h"

namespace stairmap::viewer {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Scan counts at which frames are taken: every N-th scan and the last one (one frame, at 0
/// scans, when there is no timeline).
std::vector<std::size_t> frameTargets(const ViewerController& c, const HeadlessOptions& o) {
    std::vector<std::size_t> targets;
    const std::size_t n = c.state().numScans();
    if (n == 0) {
        const int frames = o.camera == viz::CameraMode::Orbit ? o.map_orbit_frames : 1;
        targets.assign(static_cast<std::size_t>(std::max(frames, 1)), 0);
        return targets;
    }
    const auto every = static_cast<std::size_t>(std::max(o.every, 1));
    for (std::size_t k = every; k <= n; k += every) targets.push_back(k);
    if (targets.empty() || targets.back() != n) targets.push_back(n);
    return targets;
}

std::string framePath(const std::string& dir, std::size_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.png", index);
    return (std::filesystem::path(dir) / name).string();
}

}  // namespace

std::pair<int, int> parseSize(const std::string& text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 16 ||
        h < 16 || w > 8192 || h > 8192)
        throw std::invalid_argument("--size: expected WxH with 16..8192 pixels per side, e.g. "
                                    "1280x720 (got '" + text + "')");
    return {w, h};
}

HeadlessStats renderHeadless(ViewerController& c, const HeadlessOptions& o,
                             const std::function<void(std::size_t, std::size_t)>& on_frame) {
    if (o.frames_dir.empty() && o.video_path.empty())
        throw std::invalid_argument("--headless needs --frames DIR and/or --video OUT.mp4");
    const auto t0 = Clock::now();
    std::unique_ptr<viz::VideoEncoder> video;  // first: a missing ffmpeg fails before any work
    if (!o.video_path.empty())
        video = std::make_unique<viz::VideoEncoder>(o.video_path, o.width, o.height, o.video_fps);
    if (!o.frames_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(o.frames_dir, ec);
        if (ec) throw std::runtime_error(o.frames_dir + ": cannot create: " + ec.message());
    }
    viz::HeadlessRenderer renderer(o.width, o.height);
    c.state().setCamera(o.camera);
    const std::vector<std::size_t> targets = frameTargets(c, o);
    HeadlessStats stats;
    mrpt::opengl::COpenGLScene scene;
    mrpt::img::CImage image;
    for (std::size_t i = 0; i < targets.size(); ++i) {
        c.state().seek(targets[i]);
        const auto t_replay = Clock::now();
        c.sync();
        stats.replay_seconds += since(t_replay);
        const auto t_render = Clock::now();
        const viz::ViewFrame frame = c.frame();
        viz::buildViewerScene(frame, c.state().layers(), scene);
        const viz::CameraView view = viz::cameraFor(o.camera, frame.T_world_robot,
                                                    viz::frameBounds(frame),
                                                    225.0 + o.orbit_step_deg * static_cast<double>(i));
        renderer.render(scene, view, image);
        stats.render_seconds += since(t_render);
        if (!o.frames_dir.empty()) viz::savePng(image, framePath(o.frames_dir, i));
        if (video) video->addFrame(image);
        ++stats.frames;
        if (on_frame) on_frame(i + 1, targets.size());
    }
    if (video) video->finish();
    stats.seconds = since(t0);
    return stats;
}

}  // namespace stairmap::viewer
