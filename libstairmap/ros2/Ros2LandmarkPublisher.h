#pragma once
// Publishes the landmark map on ROS 2 (issue 11): visualization_msgs/MarkerArray on
// /stairmap/markers for RViz and stairmap_msgs/StaircaseArray on /stairmap/staircases for
// planners, both reliable and transient-local (keep-last 1: a late subscriber gets the current
// map; volatile subscribers such as RViz's default match too). Under a robot name the topics are
// /<robot>/stairmap/... . A republish after landmarks were removed (joined, or a map reloaded)
// starts with a DELETEALL marker.

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "live/LiveSource.h"
#include "ros2/DdsSupport.h"
#include "ros2/Ros2Options.h"

namespace stairmap::ros2 {

class Ros2LandmarkPublisher : public live::LandmarkListener {
public:
    /// Creates the participant and writers; throws std::invalid_argument for a bad topic or
    /// robot name, std::runtime_error if DDS cannot be set up.
    explicit Ros2LandmarkPublisher(const Ros2PublisherOptions& options);

    void onLandmarks(const LandmarkMap& landmarks, double stamp_s) override;
    /// The same for landmarks and floors held elsewhere (e.g. a fleet map).
    void publish(const std::vector<StaircaseLandmark>& landmarks, const std::vector<Floor>& floors,
                 double stamp_s);

    /// Subscribers currently matched on the markers topic.
    int markerSubscribers() const { return matchedReaders(markers_writer_); }
    std::size_t published() const { return published_; }
    /// Waits up to timeout_s for subscribers to acknowledge what was written (at exit).
    void flush(double timeout_s) const;
    /// The DDS topic names written, e.g. "rt/stairmap/markers".
    const std::string& markersTopic() const { return markers_dds_; }
    const std::string& staircasesTopic() const { return staircases_dds_; }

private:
    Ros2PublisherOptions options_;
    std::string markers_dds_, staircases_dds_;
    DdsEntity participant_;
    dds_entity_t markers_writer_ = 0, staircases_writer_ = 0;
    std::set<int> published_ids_;
    std::size_t published_ = 0;
};

/// The publisher as a LandmarkListener for the live runner (`stairmap live --ros2`).
std::unique_ptr<live::LandmarkListener> makeRos2Publisher(const Ros2PublisherOptions& options);

}  // namespace stairmap::ros2
