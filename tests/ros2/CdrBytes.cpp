#include "ros2/CdrBytes.h"

#include <chrono>
#include <stdexcept>
#include <thread>

#include "ros2/DdsSupport.h"

namespace stairmap::test {

CdrRoundTrip::CdrRoundTrip(const dds_topic_descriptor_t* descriptor, const std::string& topic_name) {
    ros2::useLoopbackConfigUnlessSet();
    participant_ = dds_create_participant(ros2::rosDomainId(), nullptr, nullptr);
    topic_ = dds_create_topic(participant_, descriptor, topic_name.c_str(), nullptr, nullptr);
    dds_qos_t* qos = ros2::makeQos(ros2::Reliability::Reliable, ros2::Durability::Volatile, 16);
    writer_ = dds_create_writer(participant_, topic_, qos, nullptr);
    reader_ = dds_create_reader(participant_, topic_, qos, nullptr);
    dds_delete_qos(qos);
    if (participant_ < 0 || topic_ < 0 || writer_ < 0 || reader_ < 0)
        throw std::runtime_error("CdrRoundTrip: cannot create DDS entities for " + topic_name);
}

CdrRoundTrip::~CdrRoundTrip() { dds_delete(participant_); }

namespace {
/// Takes one serialized sample, waiting up to 2 s.
ddsi_serdata* takeSerdata(dds_entity_t reader) {
    for (int i = 0; i < 200; ++i) {
        ddsi_serdata* data = nullptr;
        dds_sample_info_t info;
        if (dds_takecdr(reader, &data, 1, &info, DDS_ANY_STATE) == 1) return data;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return nullptr;
}
}  // namespace

std::vector<std::uint8_t> CdrRoundTrip::bytesOf(const void* sample) {
    if (dds_write(writer_, sample) < 0) return {};
    ddsi_serdata* data = takeSerdata(reader_);
    if (data == nullptr) return {};
    sertype_ = data->type;
    std::vector<std::uint8_t> bytes(ddsi_serdata_size(data));
    ddsi_serdata_to_ser(data, 0, bytes.size(), bytes.data());
    ddsi_serdata_unref(data);
    return bytes;
}

bool CdrRoundTrip::sampleOf(const std::vector<std::uint8_t>& bytes, void* out) {
    if (sertype_ == nullptr) return false;  // needs one bytesOf() first (for the type)
    ddsrt_iovec_t iov;
    iov.iov_base = const_cast<std::uint8_t*>(bytes.data());
    iov.iov_len = static_cast<ddsrt_iov_len_t>(bytes.size());
    ddsi_serdata* data = ddsi_serdata_from_ser_iov(sertype_, SDK_DATA, 1, &iov, bytes.size());
    if (data == nullptr) return false;  // Cyclone refused the bytes (they do not fit the type)
    if (dds_writecdr(writer_, data) < 0) return false;  // takes over the reference
    for (int i = 0; i < 200; ++i) {
        void* samples[1] = {out};
        dds_sample_info_t info;
        if (dds_take(reader_, samples, &info, 1, 1) == 1) return info.valid_data;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

}  // namespace stairmap::test
