#include "ros2/LandmarkMessages.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

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

namespace {

Eigen::Vector3d vector(const geometry_msgs_msg_dds__Point_& p) { return {p.x, p.y, p.z}; }

StaircaseLandmark landmarkOf(const stairmap_msgs_msg_dds__Staircase_& s) {
    const std::string name = "staircase " + std::to_string(s.id);
    StaircaseLandmark l;
    l.id = s.id;
    l.confirmed = s.confirmed;
    l.observations = s.observations;
    l.first_seen_s = toSeconds(s.first_seen.sec, s.first_seen.nanosec);
    l.last_seen_s = toSeconds(s.last_seen.sec, s.last_seen.nanosec);
    l.bottom_floor = s.bottom_floor_id;
    l.top_floor = s.top_floor_id;
    l.bottom_observed = s.bottom_observed;
    l.top_observed = s.top_observed;
    Staircase& st = l.stairs;
    st.direction = StairDirection::Ascending;
    st.location = vector(s.location);
    st.heading_rad = s.heading;
    st.slope_rad = s.slope;
    st.step_height = s.rise;
    st.step_depth = s.run;
    st.step_width = s.width;
    for (uint32_t k = 0; k < s.steps._length && s.steps._buffer != nullptr; ++k) {
        const auto& m = s.steps._buffer[k];
        StairEdge e;
        e.start = vector(m.start);
        e.end = vector(m.end);
        for (int j = 0; j < 4; ++j) e.cov_rho_theta(j / 2, j % 2) = m.cov_rho_theta[j];
        e.num_points = m.num_points;
        if (!e.start.allFinite() || !e.end.allFinite() || !e.cov_rho_theta.allFinite())
            throw std::invalid_argument(name + ": non-finite step " + std::to_string(k));
        st.steps.push_back(e);
        l.step_observations.push_back(m.observations);
    }
    if (st.steps.empty()) throw std::invalid_argument(name + ": no steps");
    if (!st.location.allFinite() || !std::isfinite(st.heading_rad) || !std::isfinite(st.step_height) ||
        !std::isfinite(st.step_depth) || !std::isfinite(st.step_width) || !std::isfinite(st.slope_rad))
        throw std::invalid_argument(name + ": non-finite geometry");
    return l;
}

}  // namespace

LandmarkMapState landmarkState(const stairmap_msgs_msg_dds__StaircaseArray_& message) {
    LandmarkMapState state;
    std::set<int> ids;
    for (uint32_t i = 0; i < message.staircases._length && message.staircases._buffer != nullptr; ++i) {
        StaircaseLandmark l = landmarkOf(message.staircases._buffer[i]);
        if (l.id < 0 || !ids.insert(l.id).second)
            throw std::invalid_argument("staircase " + std::to_string(l.id) + ": negative or duplicate id");
        state.next_landmark_id = std::max(state.next_landmark_id, l.id + 1);
        state.staircases.push_back(std::move(l));
    }
    std::sort(state.staircases.begin(), state.staircases.end(),
              [](const StaircaseLandmark& a, const StaircaseLandmark& b) { return a.id < b.id; });
    std::set<int> floor_ids;
    for (uint32_t i = 0; i < message.floors._length && message.floors._buffer != nullptr; ++i) {
        const auto& m = message.floors._buffer[i];
        if (m.id < 0 || !std::isfinite(m.z) || !floor_ids.insert(m.id).second)
            throw std::invalid_argument("floor " + std::to_string(m.id) + ": negative, duplicate or non-finite");
        Floor f;
        f.id = m.id;
        f.z = m.z;
        f.robot_samples = std::max(1, m.support);
        f.robot_z_sum = m.z * f.robot_samples;
        state.next_floor_id = std::max(state.next_floor_id, f.id + 1);
        state.floor_levels.push_back(f);
    }
    std::sort(state.floor_levels.begin(), state.floor_levels.end(),
              [](const Floor& a, const Floor& b) { return a.id < b.id; });
    // a link to a floor the message does not carry is dropped rather than left dangling
    for (StaircaseLandmark& l : state.staircases) {
        if (!floor_ids.count(l.bottom_floor)) l.bottom_floor = -1;
        if (!floor_ids.count(l.top_floor)) l.top_floor = -1;
    }
    return state;
}

}  // namespace stairmap::ros2
