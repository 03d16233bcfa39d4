#pragma once
// Clicking a landmark in the viewer: the ray through a pixel of an orbit camera (the model of
// CameraView, mrpt::opengl::CCamera and the window's canvas: eye on a sphere around the target,
// z up, vertical field of view), and the landmark that ray hits first.

#include <Eigen/Core>
#include <vector>

#include "map/LandmarkTypes.h"
#include "viz/ViewerCamera.h"

namespace stairmap::viz {

struct ViewRay {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();     ///< [m] the eye
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX(); ///< unit vector into the scene
};

/// The picture a camera makes: size and vertical field of view.
struct ViewImage {
    int width_px = 1280;
    int height_px = 720;
    double vertical_fov_deg = 60.0;  ///< as the viewer's window and headless renderer
};

/// The eye position of an orbit camera [m].
Eigen::Vector3d eyePosition(const CameraView& view);

/// The ray through pixel (x_px, y_px), counted from the picture's top-left corner (window and
/// mouse coordinates; pixel centres at +0.5).
ViewRay rayThroughPixel(const CameraView& view, const ViewImage& image, double x_px, double y_px);

/// [m] tread depth the viewer draws (and picks) behind each nosing of a landmark without a
/// measured run.
constexpr double kDrawnTreadDepthM = 0.25;

/// How close a click must come to a landmark to pick it.
struct PickParams {
    double edge_tolerance_m = 0.15;  ///< [m] ray-to-step-edge distance that still counts as a hit
};

/// The id of the landmark the ray meets first (a tread as the viewer draws it: one run deep behind
/// each nosing, uphill; or within edge_tolerance_m of a step edge), or -1 when it meets none.
int pickLandmark(const std::vector<StaircaseLandmark>& landmarks, const ViewRay& ray,
                 const PickParams& params = {});

}  // namespace stairmap::viz
