// Viewer scripts (`stairmap view --script`) and key bindings, applied to a controller over a
// finished map folder and to a bare state.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "viewer/ViewerScript.h"
#include "viewer/ViewerWindow.h"

namespace stairmap::viewer {
namespace {

TEST(ViewerScript, ParsesEveryVerbAndRejectsBadLines) {
    for (const char* ok : {"play", "pause", "toggle-play", "step", "step 5", "back 2", "seek 10",
                           "restart", "faster", "slower", "speed 0.25", "toggle detector",
                           "show scan", "hide floors", "select-next", "camera top", "camera-next",
                           "wait 1.5", "wait-end", "quit", "step 3  # comment"}) {
        EXPECT_NO_THROW(parseAction(ok)) << ok;
    }
    for (const char* bad : {"jump", "seek", "seek -3", "seek ten", "toggle ceiling", "camera side",
                            "play now", "step 1 2", "wait"}) {
        EXPECT_THROW(parseAction(bad), std::invalid_argument) << bad;
    }
}

TEST(ViewerScript, FileErrorsNameTheLine) {
    const auto path = std::filesystem::temp_directory_path() / "stairmap_viewer_script_bad.txt";
    std::ofstream(path) << "# a comment\n\nplay\nzoom 3\n";
    try {
        loadScript(path.string());
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string() + ":4: unknown action 'zoom'"),
                  std::string::npos) << e.what();
    }
    EXPECT_THROW(loadScript("/nonexistent/script.txt"), std::runtime_error);
}

/// A controller over an empty map folder (no timeline) is enough for the runner's timing.
ViewerController emptyMapController() {
    replay::MapFolder folder;
    folder.path = "memory";
    return ViewerController(std::move(folder), 0.35);
}

TEST(ViewerScript, RunnerHoldsActionsDuringWaits) {
    ViewerController c = emptyMapController();
    ScriptRunner runner({parseAction("hide scan"), parseAction("wait 2"), parseAction("hide voxels"),
                         parseAction("quit"), parseAction("hide floors")});
    EXPECT_TRUE(runner.update(c, 10.0));
    EXPECT_FALSE(c.state().layers().scan);
    EXPECT_TRUE(c.state().layers().voxels);
    EXPECT_TRUE(runner.update(c, 11.9));  // still waiting
    EXPECT_TRUE(c.state().layers().voxels);
    EXPECT_FALSE(runner.update(c, 12.0));  // hide voxels, then quit
    EXPECT_FALSE(c.state().layers().voxels);
    EXPECT_TRUE(c.state().layers().floors) << "actions after quit must not run";
}

TEST(ViewerScript, KeysMapToActions) {
    EXPECT_EQ(actionForKey(' ').verb, "toggle-play");
    EXPECT_EQ(actionForKey('1').arg, "scan");
    EXPECT_EQ(actionForKey('8').arg, "trajectory");
    EXPECT_EQ(actionForKey('Z').verb, "");
}

}  // namespace
}  // namespace stairmap::viewer
