#pragma once
// Test helper: a plain DDS subscriber of one ROS 2 topic on its own participant, as an
// independent ROS 2 node would be, with a bounded wait for samples.

#include <dds/dds.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>

#include "ros2/DdsSupport.h"

namespace stairmap::test {

class TestSubscriber {
public:
    TestSubscriber(const dds_topic_descriptor_t* descriptor, const std::string& dds_topic,
                   ros2::Reliability reliability = ros2::Reliability::Reliable,
                   ros2::Durability durability = ros2::Durability::Volatile, int depth = 1000)
        : participant_(ros2::createParticipant()) {
        const dds_entity_t topic = ros2::createTopic(participant_.get(), descriptor, dds_topic);
        reader_ = ros2::createReader(participant_.get(), topic, reliability, durability, depth, dds_topic);
    }
    /// Calls `handle` on each sample that arrives until `done()` or `timeout`; false on timeout.
    bool receive(const std::function<void(const void*)>& handle, const std::function<bool()>& done,
                 std::chrono::milliseconds timeout) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (!done()) {
            if (std::chrono::steady_clock::now() > end) return false;
            void* samples[8] = {nullptr};
            dds_sample_info_t infos[8];
            const dds_return_t n = dds_take(reader_, samples, infos, 8, 8);
            for (dds_return_t i = 0; i < n; ++i)
                if (infos[i].valid_data) handle(samples[i]);
            if (n > 0) dds_return_loan(reader_, samples, n);
            else std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return true;
    }
    /// Publishers matched so far.
    int publishers() const {
        dds_subscription_matched_status_t status{};
        dds_get_subscription_matched_status(reader_, &status);
        return static_cast<int>(status.current_count);
    }

private:
    ros2::DdsEntity participant_;
    dds_entity_t reader_ = 0;
};

}  // namespace stairmap::test
