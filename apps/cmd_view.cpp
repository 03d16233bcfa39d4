// `stairmap view`: replay a rawlog through the mapper (or browse a finished map folder) in a window
// with a control panel, or headless to PNG frames / MP4.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "Commands.h"
#include "io/config/MapperConfig.h"
#include "replay/MapFolder.h"
#include "replay/ReplaySession.h"
#include "viewer/ViewerController.h"
#include "viewer/ViewerHeadless.h"
#include "viewer/ViewerWindow.h"

namespace stairmap::apps {
namespace {

struct ViewOptions {
    replay::ReplayOptions replay;
    std::string source;
    bool headless = false;
    std::string frames, video, size = "1280x720", camera = "follow", script;
    std::vector<std::string> hide;
    int every = 1;
    double fps = 10.0;
};

/// --hide scan,voxels,...: layers switched off from the start (throws on an unknown name
/// before anything slow happens when `state` is null).
void hideLayers(const std::vector<std::string>& names, viewer::ViewerState* state) {
    for (const std::string& name : names) {
        viewer::Layer layer;
        if (!viewer::parseLayer(name, layer))
            throw std::invalid_argument("--hide: unknown layer '" + name + "' (scan voxels "
                                        "floor-voxels submap detector landmarks floors trajectory)");
        if (state) state->setShown(layer, false);
    }
}

std::unique_ptr<viewer::ViewerController> openSource(const ViewOptions& o) {
    if (replay::isMapFolder(o.source)) {
        // A finished map: --config only supplies the robot height (robot's-floor layer).
        const double robot_height = o.replay.config.empty()
                                        ? pipeline::SensorParams{}.robot_height_m
                                        : io::loadMapperParams(o.replay.config).sensor.robot_height_m;
        return std::make_unique<viewer::ViewerController>(replay::loadMapFolder(o.source),
                                                          robot_height);
    }
    if (std::filesystem::is_directory(o.source))
        throw std::runtime_error(o.source + ": not a `stairmap map` output folder (no landmarks.json)");
    replay::ReplayOptions r = o.replay;
    r.rawlog = o.source;
    auto session = std::make_unique<replay::ReplaySession>(r);
    if (session->numScans() == 0)
        throw std::runtime_error(o.source + ": no 3D scan with a pose in this rawlog");
    return std::make_unique<viewer::ViewerController>(std::move(session));
}

int runHeadless(viewer::ViewerController& c, const ViewOptions& o) {
    viewer::HeadlessOptions h;
    h.frames_dir = o.frames;
    h.video_path = o.video;
    h.every = o.every;
    std::tie(h.width, h.height) = viewer::parseSize(o.size);
    h.video_fps = o.fps;
    h.camera = *viz::parseCameraMode(o.camera);
    const auto stats = viewer::renderHeadless(c, h);
    std::printf("stairmap view: %zu frames %dx%d in %.2f s (render %.1f ms/frame = %.1f fps, "
                "replay %.2f s)%s%s%s%s\n", stats.frames, h.width, h.height, stats.seconds,
                1000.0 * stats.render_seconds / std::max<std::size_t>(stats.frames, 1),
                stats.render_seconds > 0 ? stats.frames / stats.render_seconds : 0.0,
                stats.replay_seconds, o.frames.empty() ? "" : " -> ", o.frames.c_str(),
                o.video.empty() ? "" : " -> ", o.video.c_str());
    return 0;
}

int runWindow(viewer::ViewerController& c, const ViewOptions& o) {
    viewer::WindowOptions w;
    w.title = "stairmap view \xe2\x80\x94 " + o.source;  // em dash
    std::tie(w.width, w.height) = viewer::parseSize(o.size);
    c.state().setCamera(*viz::parseCameraMode(o.camera));
    if (!o.script.empty()) {
        w.script = viewer::loadScript(o.script);
        w.has_script = true;
    }
    w.on_click_select = [](int id) {  // one line per click, for logs and tests
        if (id >= 0) std::printf("stairmap view: selected landmark #%d\n", id);
        else std::printf("stairmap view: selection cleared\n");
        std::fflush(stdout);
    };
    const auto stats = viewer::runViewerWindow(c, w);
    std::printf("stairmap view: %zu frames in %.1f s (%.1f fps), %zu of %zu scans\n", stats.frames,
                stats.seconds, stats.fps(), c.state().target(), c.state().numScans());
    return 0;
}

int run(const ViewOptions& o) {
    if (!viz::parseCameraMode(o.camera))
        throw std::invalid_argument("--camera: '" + o.camera + "' is not follow, top or orbit");
    viewer::parseSize(o.size);  // reject a bad size before the (slow) replay set-up
    if (o.headless && o.frames.empty() && o.video.empty())
        throw std::invalid_argument("--headless needs --frames DIR and/or --video OUT.mp4");
    hideLayers(o.hide, nullptr);
    auto controller = openSource(o);
    hideLayers(o.hide, &controller->state());
    if (controller->session() && !controller->session()->damage().empty())
        std::cerr << "stairmap view: warning: " << controller->session()->damage()
                  << " (replaying the scans before it)\n";
    return o.headless ? runHeadless(*controller, o) : runWindow(*controller, o);
}

}  // namespace

Command addViewCommand(CLI::App& app) {
    auto opt = std::make_shared<ViewOptions>();
    Command command;
    command.cli = app.add_subcommand(
        "view", "Replay a rawlog through the mapper (as `stairmap map`, same results) or browse a\n"
                "finished map folder, in a window (keys: space play/pause, Right/Left step,\n"
                "Up/Down speed, Home restart, Tab next landmark, click selects one,\n"
                "C camera, 1-8 layers, Q quit)\n"
                "or headless (--headless --frames DIR / --video OUT.mp4). Exit codes: 0 ok;\n"
                "2 bad arguments/input.");
    auto* c = command.cli;
    c->add_option("source", opt->source, "MRPT rawlog, or an output folder of `stairmap map`")
        ->required()->check(CLI::ExistingPath);
    c->add_option("--poses", opt->replay.poses, "TUM trajectory (as for `stairmap map`)")
        ->check(CLI::ExistingFile);
    c->add_option("--config", opt->replay.config, "INI file (as for `stairmap map`)");
    c->add_option("--map-in", opt->replay.map_in, "landmarks.json to continue (as for `stairmap map`)");
    c->add_flag("--headless", opt->headless, "no window: render frames off-screen");
    c->add_option("--frames", opt->frames, "headless: write frame_NNNNN.png into this folder");
    c->add_option("--video", opt->video, "headless: write an MP4 (needs ffmpeg)");
    c->add_option("--every", opt->every, "headless: a frame every N scans (default 1)")
        ->check(CLI::Range(1, 1000000));
    c->add_option("--fps", opt->fps, "headless: video frame rate (default 10)")
        ->check(CLI::Range(0.1, 240.0));
    c->add_option("--size", opt->size, "image / window size WxH (default 1280x720)");
    c->add_option("--camera", opt->camera, "follow (default), top or orbit");
    c->add_option("--hide", opt->hide, "layers to start hidden: scan voxels submap detector "
                  "landmarks floors trajectory floor-voxels (= voxels of every floor, not only the robot's)")
        ->delimiter(',');
    c->add_option("--script", opt->script, "window: run these actions (one per line; see "
                  "docs/viewer.md), closing the window at the end")->check(CLI::ExistingFile);
    command.run = [opt]() -> int { return run(*opt); };
    return command;
}

}  // namespace stairmap::apps
