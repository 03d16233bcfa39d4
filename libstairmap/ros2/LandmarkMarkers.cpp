#include "ros2/LandmarkMarkers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stairmap::ros2 {
namespace {

Eigen::Vector4f landmarkColour(const StaircaseLandmark& landmark, float alpha) {
    return landmark.confirmed ? Eigen::Vector4f(0.1f, 0.8f, 0.2f, alpha)
                              : Eigen::Vector4f(1.0f, 0.6f, 0.0f, alpha);
}

MarkerSpec edgeLines(const StaircaseLandmark& landmark) {
    MarkerSpec m;
    m.ns = landmarkNamespace(landmark.id);
    m.id = 0;
    m.type = kLineList;
    m.scale = Eigen::Vector3d(0.03, 0.0, 0.0);
    m.rgba = landmarkColour(landmark, 1.0f);
    for (const StairEdge& e : landmark.stairs.steps) {
        m.points.push_back(e.start);
        m.points.push_back(e.end);
    }
    return m;
}

/// One box per step: the tread behind each nosing (uphill), the riser's height below it.
MarkerSpec stepBoxes(const StaircaseLandmark& landmark) {
    const Staircase& s = landmark.stairs;
    MarkerSpec m;
    m.ns = landmarkNamespace(landmark.id);
    m.id = 1;
    m.type = kCubeList;
    m.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(s.heading_rad, Eigen::Vector3d::UnitZ()));
    const double run = s.step_depth > 0.0 ? s.step_depth : 0.25;
    const double rise = s.step_height > 0.0 ? s.step_height : 0.15;
    m.scale = Eigen::Vector3d(run, std::max(s.step_width, 0.05), rise);
    m.rgba = landmarkColour(landmark, 0.5f);
    const Eigen::Vector3d uphill(std::cos(s.heading_rad), std::sin(s.heading_rad), 0.0);
    const Eigen::Matrix3d R_marker_world = m.orientation.toRotationMatrix().transpose();
    for (const StairEdge& e : s.steps) {
        const Eigen::Vector3d centre = e.centre() + 0.5 * run * uphill - Eigen::Vector3d(0, 0, 0.5 * rise);
        m.points.push_back(R_marker_world * centre);
    }
    return m;
}

MarkerSpec label(const StaircaseLandmark& landmark) {
    MarkerSpec m;
    m.ns = landmarkNamespace(landmark.id);
    m.id = 2;
    m.type = kTextViewFacing;
    m.scale = Eigen::Vector3d(0.0, 0.0, 0.2);
    m.rgba = Eigen::Vector4f(1, 1, 1, 1);
    const auto& steps = landmark.stairs.steps;
    m.position = (steps.empty() ? landmark.stairs.location : steps.back().centre()) + Eigen::Vector3d(0, 0, 0.5);
    m.text = landmarkLabel(landmark);
    return m;
}

}  // namespace

std::string landmarkNamespace(int landmark_id) { return "staircase_" + std::to_string(landmark_id); }

std::string landmarkLabel(const StaircaseLandmark& landmark) {
    const Staircase& s = landmark.stairs;
    char text[160];
    std::snprintf(text, sizeof text, "stair %d: %zu steps, rise %.1f cm, run %.1f cm, width %.2f m (%s)",
                  landmark.id, s.steps.size(), 100.0 * s.step_height, 100.0 * s.step_depth, s.step_width,
                  landmark.confirmed ? "confirmed" : "tentative");
    return text;
}

std::vector<MarkerSpec> landmarkMarkers(const std::vector<StaircaseLandmark>& landmarks,
                                        bool delete_all_first) {
    std::vector<MarkerSpec> markers;
    if (delete_all_first) {
        MarkerSpec clear;
        clear.action = kDeleteAll;  // empty ns: every marker of this topic
        markers.push_back(clear);
    }
    for (const StaircaseLandmark& landmark : landmarks) {
        markers.push_back(edgeLines(landmark));
        markers.push_back(stepBoxes(landmark));
        markers.push_back(label(landmark));
    }
    return markers;
}

}  // namespace stairmap::ros2
