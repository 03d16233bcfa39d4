#pragma once
// What RViz draws for a landmark map, as plain values (turned into a visualization_msgs
// MarkerArray by MarkerArrayMessage). Per landmark one namespace "staircase_<id>" with:
//   id 0  LINE_LIST: every step edge (nosing) from start to end, 3 cm wide;
//   id 1  CUBE_LIST: one box per step (run x width x rise, below and behind each nosing), the
//         marker's pose rotated to the flight's heading so the boxes line up with it;
//   id 2  TEXT_VIEW_FACING: "stair <id>: <n> steps, rise .. cm, run .. cm, width .. m (confirmed)",
//         0.5 m above the top edge.
// Confirmed landmarks are green, tentative ones orange. All in the map's world frame.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "map/LandmarkTypes.h"

namespace stairmap::ros2 {

/// visualization_msgs/Marker type and action codes used here.
enum MarkerType : int { kLineList = 5, kCubeList = 6, kTextViewFacing = 9 };
enum MarkerAction : int { kAdd = 0, kDelete = 2, kDeleteAll = 3 };

struct MarkerSpec {
    std::string ns;
    int id = 0;
    int type = kLineList;
    int action = kAdd;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();                   ///< [m] marker pose
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();  ///< [m] line width in x; box size; text height in z
    Eigen::Vector4f rgba = Eigen::Vector4f(1, 1, 1, 1);
    std::vector<Eigen::Vector3d> points;  ///< [m] in the marker's pose frame
    std::string text;
};

/// The namespace of a landmark's markers.
std::string landmarkNamespace(int landmark_id);

/// The label of a landmark (ID and dimensions).
std::string landmarkLabel(const StaircaseLandmark& landmark);

/// Markers for `landmarks`, preceded by a DELETEALL marker when `delete_all_first` (a republish
/// that removes landmarks: RViz would otherwise keep the removed ones).
std::vector<MarkerSpec> landmarkMarkers(const std::vector<StaircaseLandmark>& landmarks,
                                        bool delete_all_first);

}  // namespace stairmap::ros2
