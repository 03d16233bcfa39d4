#include "ros2/Ros2LandmarkPublisher.h"

#include <algorithm>
#include <stdexcept>

#include "map/LandmarkMap.h"
#include "ros2/LandmarkMessages.h"

namespace stairmap::ros2 {

Ros2LandmarkPublisher::Ros2LandmarkPublisher(const Ros2PublisherOptions& options)
    : options_(options),
      markers_dds_(ddsTopicName(options.markers_topic, options.robot_name)),
      staircases_dds_(ddsTopicName(options.staircases_topic, options.robot_name)) {
    if (options_.frame_id.empty()) throw std::invalid_argument("frame id: empty");
    participant_ = createParticipant();
    const dds_entity_t p = participant_.get();
    markers_writer_ = createWriter(p, createTopic(p, &visualization_msgs_msg_dds__MarkerArray__desc, markers_dds_),
                                   Reliability::Reliable, Durability::TransientLocal, 1, markers_dds_);
    staircases_writer_ =
        createWriter(p, createTopic(p, &stairmap_msgs_msg_dds__StaircaseArray__desc, staircases_dds_),
                     Reliability::Reliable, Durability::TransientLocal, 1, staircases_dds_);
}

void Ros2LandmarkPublisher::onLandmarks(const LandmarkMap& landmarks, double stamp_s) {
    publish(landmarks.staircases(), landmarks.floors(), stamp_s);
}

void Ros2LandmarkPublisher::publish(const std::vector<StaircaseLandmark>& landmarks,
                                    const std::vector<Floor>& floors, double stamp_s) {
    std::set<int> ids;
    for (const StaircaseLandmark& l : landmarks) ids.insert(l.id);
    // any landmark shown before and gone now: RViz keeps markers until told, so clear first
    const bool removed = !std::includes(ids.begin(), ids.end(), published_ids_.begin(), published_ids_.end());
    const MarkerArrayMessage markers(landmarkMarkers(landmarks, removed), stamp_s, options_.frame_id);
    const StaircaseArrayMessage staircases(landmarks, floors, stamp_s, options_.frame_id);
    const dds_return_t a = dds_write(markers_writer_, markers.sample());
    const dds_return_t b = dds_write(staircases_writer_, staircases.sample());
    if (a < 0 || b < 0)
        throw std::runtime_error("DDS write on " + (a < 0 ? markers_dds_ : staircases_dds_) + ": " +
                                 dds_strretcode(a < 0 ? a : b));
    published_ids_ = std::move(ids);
    ++published_;
}

void Ros2LandmarkPublisher::flush(double timeout_s) const {
    const dds_duration_t timeout = static_cast<dds_duration_t>(timeout_s * 1e9);
    dds_wait_for_acks(markers_writer_, timeout);
    dds_wait_for_acks(staircases_writer_, timeout);
}

std::unique_ptr<live::LandmarkListener> makeRos2Publisher(const Ros2PublisherOptions& options) {
    return std::make_unique<Ros2LandmarkPublisher>(options);
}

}  // namespace stairmap::ros2
