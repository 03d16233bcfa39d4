#include "ros2/LandmarkMessages.h"

#include <cmath>

#include "ros2/DdsSupport.h"
#include "ros2/MessageBuilders.h"

namespace stairmap::ros2 {
namespace {

geometry_msgs_msg_dds__Point_ point(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

void meanAndSigma(const std::vector<double>& values, double& mean, double& sigma) {
    mean = sigma = 0.0;
    if (values.empty()) return;
    for (double v : values) mean += v;
    mean /= double(values.size());
    if (values.size() < 2) return;
    double sum_sq = 0.0;
    for (double v : values) sum_sq += (v - mean) * (v - mean);
    sigma = std::sqrt(sum_sq / double(values.size() - 1));
}

builtin_interfaces_msg_dds__Time_ time(double seconds) {
    const RosTime t = toRosTime(seconds);
    return {t.sec, t.nanosec};
}

}  // namespace

MarkerArrayMessage::MarkerArrayMessage(const std::vector<MarkerSpec>& markers, double stamp_s,
                                       const std::string& frame_id)
    : frame_id_(frame_id), specs_(markers) {
    points_.resize(specs_.size());
    markers_.resize(specs_.size());
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        const MarkerSpec& s = specs_[i];
        visualization_msgs_msg_dds__Marker_& m = markers_[i];
        m = {};
        setHeader(m.header, stamp_s, frame_id_);
        m.ns = const_cast<char*>(s.ns.c_str());
        m.id = s.id;
        m.type = s.type;
        m.action = s.action;
        m.pose.position = point(s.position);
        m.pose.orientation = {s.orientation.x(), s.orientation.y(), s.orientation.z(), s.orientation.w()};
        m.scale = {s.scale.x(), s.scale.y(), s.scale.z()};
        m.color = {s.rgba[0], s.rgba[1], s.rgba[2], s.rgba[3]};
        for (const Eigen::Vector3d& p : s.points) points_[i].push_back(point(p));
        pointSequenceAt(m.points, points_[i]);
        m.text = const_cast<char*>(s.text.c_str());
        // unused strings must still be valid (empty) for the serializer
        m.texture_resource = m.mesh_resource = m.mesh_file.filename = const_cast<char*>(empty_.c_str());
        m.texture.header.frame_id = m.texture.format = const_cast<char*>(empty_.c_str());
    }
    pointSequenceAt(msg_.markers, markers_);
}

FlightDimensions flightDimensions(const Staircase& stairs) {
    const auto& steps = stairs.steps;
    const Eigen::Vector2d heading(std::cos(stairs.heading_rad), std::sin(stairs.heading_rad));
    std::vector<double> rises, runs, widths;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        widths.push_back(steps[i].length());
        if (i == 0) continue;
        const Eigen::Vector3d d = steps[i].centre() - steps[i - 1].centre();
        rises.push_back(std::abs(d.z()));
        runs.push_back(std::abs(d.head<2>().dot(heading)));
    }
    FlightDimensions f;
    meanAndSigma(rises, f.rise, f.rise_sigma);
    meanAndSigma(runs, f.run, f.run_sigma);
    meanAndSigma(widths, f.width, f.width_sigma);
    return f;
}

StaircaseArrayMessage::StaircaseArrayMessage(const std::vector<StaircaseLandmark>& landmarks,
                                             const std::vector<Floor>& floors, double stamp_s,
                                             const std::string& frame_id)
    : frame_id_(frame_id) {
    setHeader(msg_.header, stamp_s, frame_id_);
    steps_.resize(landmarks.size());
    for (std::size_t i = 0; i < landmarks.size(); ++i) {
        const StaircaseLandmark& l = landmarks[i];
        for (std::size_t k = 0; k < l.stairs.steps.size(); ++k) {
            const StairEdge& e = l.stairs.steps[k];
            stairmap_msgs_msg_dds__StairStep_ step{};
            step.start = point(e.start);
            step.end = point(e.end);
            for (int j = 0; j < 4; ++j) step.cov_rho_theta[j] = e.cov_rho_theta(j / 2, j % 2);
            step.num_points = e.num_points;
            step.observations = k < l.step_observations.size() ? l.step_observations[k] : 0;
            steps_[i].push_back(step);
        }
        stairmap_msgs_msg_dds__Staircase_ s{};
        s.id = l.id;
        s.direction = 0;  // landmarks are canonical: ascending, steps bottom to top
        s.confirmed = l.confirmed;
        s.observations = l.observations;
        s.first_seen = time(l.first_seen_s);
        s.last_seen = time(l.last_seen_s);
        s.location = point(l.stairs.location);
        s.heading = l.stairs.heading_rad;
        s.slope = l.stairs.slope_rad;
        const FlightDimensions d = flightDimensions(l.stairs);
        s.rise = l.stairs.step_height;
        s.run = l.stairs.step_depth;
        s.width = l.stairs.step_width;
        s.rise_sigma = d.rise_sigma;
        s.run_sigma = d.run_sigma;
        s.width_sigma = d.width_sigma;
        pointSequenceAt(s.steps, steps_[i]);
        s.bottom_floor_id = l.bottom_floor;
        s.top_floor_id = l.top_floor;
        s.bottom_observed = l.bottom_observed;
        s.top_observed = l.top_observed;
        staircases_.push_back(s);
    }
    for (const Floor& f : floors) floors_.push_back({f.id, f.z, f.support()});
    pointSequenceAt(msg_.staircases, staircases_);
    pointSequenceAt(msg_.floors, floors_);
}

}  // namespace stairmap::ros2
