#include "viz/HeadlessRenderer.h"

#include <mrpt/opengl/CFBORender.h>
#include <unistd.h>

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace stairmap::viz {

HeadlessRenderer::HeadlessRenderer(int width, int height) : width_(width), height_(height) {
    if (width < 16 || height < 16 || width > 8192 || height > 8192)
        throw std::invalid_argument("image size must be 16..8192 pixels per side");
    try {
        fbo_ = std::make_unique<mrpt::opengl::CFBORender>(width, height);
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("off-screen OpenGL (EGL) unavailable: ") + e.what());
    }
}

HeadlessRenderer::~HeadlessRenderer() = default;

void HeadlessRenderer::render(const mrpt::opengl::COpenGLScene& scene, const CameraView& view,
                              mrpt::img::CImage& out) {
    mrpt::opengl::CCamera& cam = fbo_->getCamera(scene);
    cam.setProjectiveModel(true);
    cam.setProjectiveFOVdeg(60.0f);
    cam.setPointingAt(static_cast<float>(view.target.x()), static_cast<float>(view.target.y()),
                      static_cast<float>(view.target.z()));
    cam.setZoomDistance(static_cast<float>(view.distance_m));
    cam.setAzimuthDegrees(static_cast<float>(view.azimuth_deg));
    cam.setElevationDegrees(static_cast<float>(view.elevation_deg));
    fbo_->render_RGB(scene, out);
}

void savePng(const mrpt::img::CImage& image, const std::string& path) {
    if (!image.saveToFile(path)) throw std::runtime_error(path + ": cannot write the PNG");
}

bool programOnPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (path == nullptr) return false;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
        if (::access(candidate.c_str(), X_OK) == 0) return true;
    }
    return false;
}

VideoEncoder::VideoEncoder(const std::string& path, int width, int height, double fps)
    : path_(path), width_(width), height_(height) {
    if (!programOnPath("ffmpeg"))
        throw std::runtime_error("ffmpeg not found on PATH (Debian package ffmpeg): needed for "
                                 "--video " + path);
    std::ostringstream cmd;  // yuv420p needs even sizes: pad by one pixel when odd
    cmd << "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " << width << "x" << height
        << " -r " << fps << " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p -preset veryfast '" << path
        << "'";
    pipe_ = ::popen(cmd.str().c_str(), "w");
    if (pipe_ == nullptr) throw std::runtime_error(path + ": cannot start ffmpeg");
}

VideoEncoder::~VideoEncoder() {
    if (pipe_ != nullptr) ::pclose(pipe_);
}

void VideoEncoder::addFrame(const mrpt::img::CImage& rgb) {
    std::vector<unsigned char> row(static_cast<std::size_t>(3 * width_));
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            for (int ch = 0; ch < 3; ++ch)  // CImage stores BGR
                row[3 * x + ch] = *rgb(x, y, static_cast<unsigned>(2 - ch));
        }
        if (std::fwrite(row.data(), 1, row.size(), pipe_) != row.size())
            throw std::runtime_error(path_ + ": ffmpeg stopped accepting frames");
    }
}

void VideoEncoder::finish() {
    if (pipe_ == nullptr) return;
    const int status = ::pclose(pipe_);
    pipe_ = nullptr;
    if (status != 0) throw std::runtime_error(path_ + ": ffmpeg failed (status " +
                                              std::to_string(status) + ")");
}

}  // namespace stairmap::viz
