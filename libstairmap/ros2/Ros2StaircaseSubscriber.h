#pragma once
// Subscribes to several robots' landmark maps, /<robot>/stairmap/staircases
// (stairmap_msgs/StaircaseArray, reliable, transient-local: a robot's current map arrives on
// joining, also from a robot that started first). For `stairmap fleet --ros2`.

#include <cstddef>
#include <string>
#include <vector>

#include "map/LandmarkTypes.h"
#include "ros2/DdsSupport.h"

namespace stairmap::ros2 {

class Ros2StaircaseSubscriber {
public:
    /// One reader per robot name (throws std::invalid_argument naming a bad name,
    /// std::runtime_error if DDS cannot be set up).
    explicit Ros2StaircaseSubscriber(const std::vector<std::string>& robot_names,
                                     const std::string& topic = "/stairmap/staircases");

    struct Received {
        std::size_t robot = 0;    ///< index into robot_names
        LandmarkMapState state;   ///< the robot's whole map, in its own frame
        double stamp_s = 0.0;     ///< [s] header stamp
    };
    /// The maps that arrived, waiting up to timeout_s for the first. Malformed ones are counted.
    std::vector<Received> poll(double timeout_s);
    std::size_t malformed() const { return malformed_; }
    /// Why the last malformed map was refused ("robot a: staircase 3: no steps").
    const std::string& lastProblem() const { return last_problem_; }

private:
    std::vector<std::string> names_;
    DdsEntity participant_;
    DdsEntity waitset_;
    std::vector<dds_entity_t> readers_;
    std::size_t malformed_ = 0;
    std::string last_problem_;
};

}  // namespace stairmap::ros2
