// `stairmap view` in a real window: Xvfb on a free display, the viewer driven by key events
// (xdotool) on top of a short script, screenshots (xwd) before and after stepping. Everything is
// bounded in time and the processes started here are ended here.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <mrpt/img/CImage.h>
#include <thread>

#include "CliRunner.h"
#include "ImageChecks.h"
#include "viz/ViewerScene.h"

extern char** environ;

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// A child process started with posix_spawnp, terminated (SIGTERM, then SIGKILL) on destruction.
class Child {
public:
    Child(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env = {},
          const std::string& stdout_path = "/dev/null", const std::string& stderr_path = "/dev/null") {
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        env_ = extra_env;
        for (char** e = environ; *e != nullptr; ++e) env_.emplace_back(*e);
        std::vector<char*> envp;
        for (const auto& e : env_) envp.push_back(const_cast<char*>(e.c_str()));
        envp.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 1, stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (posix_spawnp(&pid_, args[0], &actions, nullptr, args.data(), envp.data()) != 0) pid_ = -1;
        posix_spawn_file_actions_destroy(&actions);
    }
    ~Child() {
        if (pid_ <= 0 || exited_) return;
        kill(pid_, SIGTERM);
        for (int i = 0; i < 50 && !poll(); ++i) std::this_thread::sleep_for(100ms);
        if (!exited_) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }
    bool started() const { return pid_ > 0; }
    /// True once the child has exited (status in exitCode()).
    bool poll() {
        int status = 0;
        if (!exited_ && waitpid(pid_, &status, WNOHANG) == pid_) {
            exited_ = true;
            code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
        }
        return exited_;
    }
    int exitCode() const { return code_; }

private:
    pid_t pid_ = -1;
    bool exited_ = false;
    int code_ = -1;
    std::vector<std::string> env_;
};

/// The first display number in 90..190 with neither a lock file nor a socket.
int freeDisplay() {
    for (int d = 90; d < 190; ++d) {
        if (!fs::exists("/tmp/.X" + std::to_string(d) + "-lock") &&
            !fs::exists("/tmp/.X11-unix/X" + std::to_string(d)))
            return d;
    }
    return -1;
}

template <class Pred>
bool waitFor(Pred pred, std::chrono::seconds limit) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
        if (pred()) return true;
        std::this_thread::sleep_for(200ms);
    }
    return false;
}

int sh(const std::string& display, const std::string& command) {
    const int status = std::system(("export DISPLAY=" + display + "; " + command).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

mrpt::img::CImage screenshot(const std::string& display, const std::string& path) {
    EXPECT_EQ(sh(display, "xwd -root -silent | convert xwd:- '" + path + "'"), 0);
    mrpt::img::CImage img;
    EXPECT_TRUE(img.loadFromFile(path));
    return img;
}

TEST(ViewWindow, StepsWithKeysAndShowsTheLandmarks) {
    const std::string dir = cliScratchDir("view", "window");
    const int d = freeDisplay();
    ASSERT_GT(d, 0) << "no free X display number";
    const std::string display = ":" + std::to_string(d);
    Child xvfb({"Xvfb", display, "-screen", "0", "1280x800x24", "-nolisten", "tcp"});
    ASSERT_TRUE(xvfb.started()) << "Xvfb (Debian xvfb) not found";
    ASSERT_TRUE(waitFor([&] { return fs::exists("/tmp/.X11-unix/X" + std::to_string(d)); }, 15s));

    // The script starts at scan 20 (nothing detected yet) and keeps the window open at most 90 s.
    std::ofstream(dir + "/script.txt") << "seek 20\nwait 90\nquit\n";
    const std::string data = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/";
    Child viewer({"timeout", "150", STAIRMAP_BIN, "view", data + "two_floor.rawlog", "--poses",
                  data + "poses.tum", "--config",
                  std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini", "--script",
                  dir + "/script.txt"},
                 // Under ASan: 112 bytes leak in a GL/X11 module that is unloaded before exit (LSan
                 // shows "<unknown module>", so no suppression can name it); leak checking is off
                 // for this child only. Placed first, this entry wins over the inherited one.
                 {"DISPLAY=" + display, "ASAN_OPTIONS=detect_leaks=0"}, dir + "/stdout.txt",
                 dir + "/stderr.txt");
    ASSERT_TRUE(viewer.started());
    const std::string find = "xdotool search --name 'stairmap view' >/dev/null 2>&1";
    ASSERT_TRUE(waitFor([&] { return sh(display, find) == 0; }, 60s)) << "no window appeared";
    std::this_thread::sleep_for(6s);  // the first frames (scan 20) are drawn
    const auto before = screenshot(display, dir + "/before.png");

    // Step to the end (63 x right arrow: both flights get confirmed), then the top camera.
    std::string keys;
    for (int i = 0; i < 63; ++i) keys += " Right";
    ASSERT_EQ(sh(display, "xdotool search --name 'stairmap view' windowfocus >/dev/null 2>&1; "
                          "xdotool key --delay 30" + keys + " c"), 0);
    std::this_thread::sleep_for(8s);
    const auto after = screenshot(display, dir + "/after.png");
    EXPECT_GT(differingFraction(before, after), 0.05) << "the window did not change after stepping";
    EXPECT_EQ(pixelsNear(before, viz::kConfirmedRgb), 0u) << "a confirmed landmark at scan 20?";
    EXPECT_GT(pixelsNear(after, viz::kConfirmedRgb), 50u) << "no confirmed-landmark colour";

    // A click on a drawn landmark edge selects it; a click on the empty corner clears it.
    const auto [lx, ly] = densestPixel(after, viz::kConfirmedRgb);
    ASSERT_GE(lx, 0);
    ASSERT_EQ(sh(display, "xdotool mousemove " + std::to_string(lx) + " " + std::to_string(ly) +
                              " click 1"), 0);
    const auto stdoutHas = [&](const std::string& text) {
        return readText(dir + "/stdout.txt").find(text) != std::string::npos;
    };
    EXPECT_TRUE(waitFor([&] { return stdoutHas("selected landmark #"); }, 10s))
        << "clicking the landmark at (" << lx << ", " << ly << ") selected nothing";
    ASSERT_EQ(sh(display, "xdotool mousemove 1270 710 click 1"), 0);
    EXPECT_TRUE(waitFor([&] { return stdoutHas("selection cleared"); }, 10s))
        << "clicking empty space did not clear the selection";

    sh(display, "xdotool key q");
    EXPECT_TRUE(waitFor([&] { return viewer.poll(); }, 30s)) << "the viewer did not quit on Q";
    EXPECT_EQ(viewer.exitCode(), 0) << readText(dir + "/stderr.txt");
    EXPECT_NE(readText(dir + "/stdout.txt").find("frames in"), std::string::npos);
}

}  // namespace
}  // namespace stairmap::test
