#pragma once
// The viewer without a window: the same scene rendered off-screen (CFBORender) to numbered PNGs
// and/or an MP4 through ffmpeg.

#include <functional>
#include <string>

#include "viewer/ViewerController.h"

namespace stairmap::viewer {

struct HeadlessOptions {
    std::string frames_dir;   ///< PNGs frame_00000.png ... written here ("" = none)
    std::string video_path;   ///< MP4 written by ffmpeg ("" = none)
    int every = 1;            ///< a frame every N scans (the last scan always gets one)
    int width = 1280;         ///< [px]
    int height = 720;         ///< [px]
    double video_fps = 10.0;  ///< frames per second of the video
    viz::CameraMode camera = viz::CameraMode::Follow;
    double orbit_step_deg = 2.0;  ///< [deg] orbit camera turn per frame
    int map_orbit_frames = 36;    ///< frames of a finished map with the orbit camera (one turn)
};

struct HeadlessStats {
    std::size_t frames = 0;
    double seconds = 0.0;         ///< [s] wall time of the whole run (replay + render + write)
    double render_seconds = 0.0;  ///< [s] scene building + off-screen rendering only
    double replay_seconds = 0.0;  ///< [s] mapping (the replay) only
};

/// Renders the frames. Throws std::runtime_error (missing ffmpeg, unwritable directory, no
/// EGL); `on_frame(index, total)` is called after each frame (progress; may be empty).
HeadlessStats renderHeadless(ViewerController& controller, const HeadlessOptions& options,
                             const std::function<void(std::size_t, std::size_t)>& on_frame = {});

/// "1280x720" -> (1280, 720); throws std::invalid_argument otherwise.
std::pair<int, int> parseSize(const std::string& text);

}  // namespace stairmap::viewer
