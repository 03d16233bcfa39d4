#pragma once
// Off-screen rendering of a viewer scene to images, with no display (CFBORender on EGL; Mesa's
// software device on a machine without a GPU), and the frames piped to ffmpeg for an MP4.

#include <cstdio>
#include <memory>
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <string>

#include "viz/ViewerCamera.h"

namespace mrpt::opengl {
class CFBORender;
}

namespace stairmap::viz {

class HeadlessRenderer {
public:
    /// Creates the off-screen context (throws std::runtime_error if OpenGL/EGL is unavailable).
    HeadlessRenderer(int width, int height);
    ~HeadlessRenderer();

    /// Renders `scene` seen from `view` into `out` (RGB, width x height).
    void render(const mrpt::opengl::COpenGLScene& scene, const CameraView& view,
                mrpt::img::CImage& out);
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    std::unique_ptr<mrpt::opengl::CFBORender> fbo_;
};

/// Writes `image` as PNG; throws std::runtime_error naming the path on failure.
void savePng(const mrpt::img::CImage& image, const std::string& path);

/// Feeds RGB frames to `ffmpeg` (H.264 MP4). The constructor throws std::runtime_error
/// "ffmpeg not found on PATH (Debian package ffmpeg) ..." when ffmpeg is missing.
class VideoEncoder {
public:
    VideoEncoder(const std::string& path, int width, int height, double fps);
    ~VideoEncoder();
    void addFrame(const mrpt::img::CImage& rgb);
    /// Waits for ffmpeg; throws std::runtime_error naming the output if it failed.
    void finish();

private:
    std::string path_;
    int width_, height_;
    std::FILE* pipe_ = nullptr;
};

/// True if `program` is an executable file in a directory of $PATH.
bool programOnPath(const std::string& program);

}  // namespace stairmap::viz
