#pragma once
// The few Cyclone DDS calls every ROS 2 endpoint of stairmap shares: the participant on the ROS 2
// domain with the loopback configuration, ROS-named topics and QoS, and an owning entity handle.
// Behaves like a ROS 2 node on rmw_cyclonedds (Jazzy): topic "rt/<name>", type names
// "<pkg>::msg::dds_::<Type>_", plain CDR (XCDR1), keyless, no type information.

#include <dds/dds.h>

#include <string>

namespace stairmap::ros2 {

/// Owns one DDS entity (participant, topic, reader, writer, waitset); deleting it deletes its
/// children. Move-only.
class DdsEntity {
public:
    DdsEntity() = default;
    explicit DdsEntity(dds_entity_t entity) : entity_(entity) {}
    DdsEntity(DdsEntity&& other) noexcept : entity_(other.entity_) { other.entity_ = 0; }
    DdsEntity& operator=(DdsEntity&& other) noexcept;
    DdsEntity(const DdsEntity&) = delete;
    DdsEntity& operator=(const DdsEntity&) = delete;
    ~DdsEntity();
    dds_entity_t get() const { return entity_; }

private:
    dds_entity_t entity_ = 0;
};

/// The DDS domain: ROS_DOMAIN_ID (0..232; default 0). Throws std::runtime_error naming the
/// variable if it is set to something else.
dds_domainid_t rosDomainId();

/// Before the first participant: if CYCLONEDDS_URI is unset, points it at the loopback-only
/// configuration shipped as config/cyclonedds_loopback.xml (its build-time copy if the source
/// tree is gone). An existing CYCLONEDDS_URI is used as it is. Returns the configuration used.
std::string useLoopbackConfigUnlessSet();

/// Creates a participant on rosDomainId() (after useLoopbackConfigUnlessSet()). Throws
/// std::runtime_error with Cyclone's reason on failure.
DdsEntity createParticipant();

/// "rt" + the fully qualified ROS name: ros_name "/points" or "points" -> "rt/points";
/// with a namespace "robot1": "rt/robot1/points". Throws std::invalid_argument naming the topic
/// if it is empty or has characters ROS does not allow (letters, digits, '_' and '/').
std::string ddsTopicName(const std::string& ros_name, const std::string& ros_namespace = "");

/// Creates (or finds) the topic. The descriptor's type name travels as it is; type information
/// is not generated (idlc -t). Throws std::runtime_error naming the topic.
dds_entity_t createTopic(dds_entity_t participant, const dds_topic_descriptor_t* descriptor,
                         const std::string& dds_topic_name);

enum class Reliability { BestEffort, Reliable };
enum class Durability { Volatile, TransientLocal };

/// QoS as rmw_cyclonedds sets it: keep-last `depth`, the given reliability and durability,
/// data representation XCDR1 only. Owned by the caller (dds_delete_qos).
dds_qos_t* makeQos(Reliability reliability, Durability durability, int depth);

/// Reader / writer with that QoS. Throw std::runtime_error naming the topic.
dds_entity_t createReader(dds_entity_t participant, dds_entity_t topic, Reliability reliability,
                          Durability durability, int depth, const std::string& topic_name);
dds_entity_t createWriter(dds_entity_t participant, dds_entity_t topic, Reliability reliability,
                          Durability durability, int depth, const std::string& topic_name);

/// Number of readers currently matched with `writer` (0 on error).
int matchedReaders(dds_entity_t writer);

/// [s] a ROS builtin_interfaces/Time as seconds, and back (nanoseconds rounded; negative and
/// non-finite times become 0).
struct RosTime { int sec = 0; unsigned nanosec = 0; };
double toSeconds(int sec, unsigned nanosec);
RosTime toRosTime(double seconds);

}  // namespace stairmap::ros2
