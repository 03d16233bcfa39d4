#include "ros2/Ros2StaircaseSubscriber.h"

#include <stdexcept>

#include "ros2/LandmarkMessages.h"
#include "ros2/MessageBuilders.h"

namespace stairmap::ros2 {

Ros2StaircaseSubscriber::Ros2StaircaseSubscriber(const std::vector<std::string>& robot_names,
                                                 const std::string& topic)
    : names_(robot_names) {
    std::vector<std::string> dds_names;
    for (const std::string& robot : names_) {
        if (robot.empty()) throw std::invalid_argument("robot name: empty");
        dds_names.push_back(ddsTopicName(topic, robot));
    }
    participant_ = createParticipant();
    waitset_ = DdsEntity(dds_create_waitset(participant_.get()));
    for (const std::string& name : dds_names) {
        const dds_entity_t t = createTopic(participant_.get(), &stairmap_msgs_msg_dds__StaircaseArray__desc, name);
        const dds_entity_t reader =
            createReader(participant_.get(), t, Reliability::Reliable, Durability::TransientLocal, 1, name);
        dds_waitset_attach(waitset_.get(), dds_create_readcondition(reader, DDS_ANY_STATE), 0);
        readers_.push_back(reader);
    }
}

std::vector<Ros2StaircaseSubscriber::Received> Ros2StaircaseSubscriber::poll(double timeout_s) {
    dds_waitset_wait(waitset_.get(), nullptr, 0, static_cast<dds_duration_t>(timeout_s * 1e9));
    std::vector<Received> received;
    for (std::size_t r = 0; r < readers_.size(); ++r) {
        void* samples[4] = {nullptr};
        dds_sample_info_t infos[4];
        const dds_return_t n = dds_take(readers_[r], samples, infos, 4, 4);
        for (dds_return_t i = 0; i < n; ++i) {
            if (!infos[i].valid_data) continue;
            const auto& message = *static_cast<const stairmap_msgs_msg_dds__StaircaseArray_*>(samples[i]);
            try {
                received.push_back({r, landmarkState(message), headerStamp(message.header)});
            } catch (const std::invalid_argument& e) {
                ++malformed_;
                last_problem_ = "robot " + names_[r] + ": " + e.what();
            }
        }
        if (n > 0) dds_return_loan(readers_[r], samples, n);
    }
    return received;
}

}  // namespace stairmap::ros2
