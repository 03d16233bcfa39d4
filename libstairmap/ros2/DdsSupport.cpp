#include "ros2/DdsSupport.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "ros2/LoopbackConfig.h"  // generated: kLoopbackConfigPath, kLoopbackConfigXml

namespace stairmap::ros2 {

DdsEntity& DdsEntity::operator=(DdsEntity&& other) noexcept {
    if (this != &other) {
        if (entity_ > 0) dds_delete(entity_);
        entity_ = other.entity_;
        other.entity_ = 0;
    }
    return *this;
}

DdsEntity::~DdsEntity() {
    if (entity_ > 0) dds_delete(entity_);
}

dds_domainid_t rosDomainId() {
    const char* text = std::getenv("ROS_DOMAIN_ID");
    if (text == nullptr || *text == '\0') return 0;
    char* end = nullptr;
    const long id = std::strtol(text, &end, 10);
    // ROS 2 allows 0..232 (the port arithmetic of the DDSI spec leaves no room above)
    if (*end != '\0' || id < 0 || id > 232)
        throw std::runtime_error(std::string("ROS_DOMAIN_ID: '") + text +
                                 "' is not a domain id (an integer 0..232)");
    return static_cast<dds_domainid_t>(id);
}

std::string useLoopbackConfigUnlessSet() {
    const char* existing = std::getenv("CYCLONEDDS_URI");
    if (existing != nullptr && *existing != '\0') return existing;
    // the shipped file if the source tree is still there (so edits take effect), else its copy
    std::string config = std::ifstream(kLoopbackConfigPath).good()
                             ? std::string("file://") + kLoopbackConfigPath
                             : std::string(kLoopbackConfigXml);
    setenv("CYCLONEDDS_URI", config.c_str(), 0);
    return std::getenv("CYCLONEDDS_URI");
}

DdsEntity createParticipant() {
    const dds_domainid_t domain = rosDomainId();
    useLoopbackConfigUnlessSet();
    const dds_entity_t participant = dds_create_participant(domain, nullptr, nullptr);
    if (participant < 0)
        throw std::runtime_error("DDS participant on domain " + std::to_string(domain) + ": " +
                                 dds_strretcode(participant) + " (check CYCLONEDDS_URI)");
    return DdsEntity(participant);
}

std::string ddsTopicName(const std::string& ros_name, const std::string& ros_namespace) {
    auto check = [&](const std::string& name, const char* what) {
        for (char c : name)
            if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/'))
                throw std::invalid_argument(std::string(what) + " '" + name +
                                            "': only letters, digits, '_' and '/' are allowed");
    };
    check(ros_name, "topic");
    check(ros_namespace, "namespace");
    auto trim = [](std::string s) {
        while (!s.empty() && s.front() == '/') s.erase(s.begin());
        while (!s.empty() && s.back() == '/') s.pop_back();
        return s;
    };
    const std::string name = trim(ros_name), space = trim(ros_namespace);
    if (name.empty()) throw std::invalid_argument("topic '" + ros_name + "': empty name");
    return space.empty() ? "rt/" + name : "rt/" + space + "/" + name;
}

dds_entity_t createTopic(dds_entity_t participant, const dds_topic_descriptor_t* descriptor,
                         const std::string& dds_topic_name) {
    const dds_entity_t topic =
        dds_create_topic(participant, descriptor, dds_topic_name.c_str(), nullptr, nullptr);
    if (topic < 0)
        throw std::runtime_error("DDS topic " + dds_topic_name + " (" + descriptor->m_typename +
                                 "): " + dds_strretcode(topic));
    return topic;
}

dds_qos_t* makeQos(Reliability reliability, Durability durability, int depth) {
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos,
                         reliability == Reliability::Reliable ? DDS_RELIABILITY_RELIABLE
                                                              : DDS_RELIABILITY_BEST_EFFORT,
                         DDS_SECS(1));
    dds_qset_durability(qos, durability == Durability::TransientLocal
                                 ? DDS_DURABILITY_TRANSIENT_LOCAL
                                 : DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, depth);
    const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
    dds_qset_data_representation(qos, 1, &xcdr1);
    return qos;
}

namespace {
dds_entity_t checked(dds_entity_t entity, const char* what, const std::string& topic_name) {
    if (entity < 0)
        throw std::runtime_error(std::string("DDS ") + what + " on " + topic_name + ": " +
                                 dds_strretcode(entity));
    return entity;
}
}  // namespace

dds_entity_t createReader(dds_entity_t participant, dds_entity_t topic, Reliability reliability,
                          Durability durability, int depth, const std::string& topic_name) {
    dds_qos_t* qos = makeQos(reliability, durability, depth);
    const dds_entity_t reader = dds_create_reader(participant, topic, qos, nullptr);
    dds_delete_qos(qos);
    return checked(reader, "reader", topic_name);
}

dds_entity_t createWriter(dds_entity_t participant, dds_entity_t topic, Reliability reliability,
                          Durability durability, int depth, const std::string& topic_name) {
    dds_qos_t* qos = makeQos(reliability, durability, depth);
    const dds_entity_t writer = dds_create_writer(participant, topic, qos, nullptr);
    dds_delete_qos(qos);
    return checked(writer, "writer", topic_name);
}

int matchedReaders(dds_entity_t writer) {
    dds_publication_matched_status_t status{};
    if (dds_get_publication_matched_status(writer, &status) != DDS_RETCODE_OK) return 0;
    return static_cast<int>(status.current_count);
}

double toSeconds(int sec, unsigned nanosec) { return sec + nanosec * 1e-9; }

RosTime toRosTime(double seconds) {
    if (!std::isfinite(seconds) || seconds <= 0.0 || seconds > 2147483647.0) return {};
    RosTime t;
    double whole = std::floor(seconds);
    double nanos = std::round((seconds - whole) * 1e9);
    if (nanos >= 1e9) { whole += 1.0; nanos = 0.0; }
    t.sec = static_cast<int>(whole);
    t.nanosec = static_cast<unsigned>(nanos);
    return t;
}

}  // namespace stairmap::ros2
