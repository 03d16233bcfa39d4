#include "ros2/MessageBuilders.h"

#include <cmath>
#include <cstring>

#include "ros2/DdsSupport.h"

namespace stairmap::ros2 {

void setHeader(std_msgs_msg_dds__Header_& header, double stamp_s, const std::string& frame_id) {
    const RosTime t = toRosTime(stamp_s);
    header.stamp.sec = t.sec;
    header.stamp.nanosec = t.nanosec;
    header.frame_id = const_cast<char*>(frame_id.c_str());  // DDS only reads it
}

double headerStamp(const std_msgs_msg_dds__Header_& header) {
    return toSeconds(header.stamp.sec, header.stamp.nanosec);
}

CloudMessage::CloudMessage(const PointCloud& points, double stamp_s, const std::string& frame_id)
    : frame_id_(frame_id) {
    setHeader(msg_.header, stamp_s, frame_id_);
    for (std::size_t i = 0; i < names_.size(); ++i) {
        sensor_msgs_msg_dds__PointField_ field{};
        field.name = const_cast<char*>(names_[i].c_str());
        field.offset = static_cast<uint32_t>(4 * i);
        field.datatype = kFloat32;
        field.count = 1;
        fields_.push_back(field);
    }
    pointSequenceAt(msg_.fields, fields_);
    data_.resize(points.size() * 12);
    for (std::size_t i = 0; i < points.size(); ++i) std::memcpy(&data_[12 * i], points[i].data(), 12);
    pointSequenceAt(msg_.data, data_);
    msg_.height = 1;
    msg_.width = static_cast<uint32_t>(points.size());
    msg_.point_step = 12;
    msg_.row_step = static_cast<uint32_t>(12 * points.size());
    msg_.is_bigendian = false;  // x86/ARM hosts are little-endian; CloudDecoder swaps otherwise
    msg_.is_dense = true;
}

OdometryMessage::OdometryMessage(const Eigen::Isometry3d& T_frame_child, double stamp_s,
                                 const std::string& frame_id, const std::string& child_frame_id)
    : frame_id_(frame_id), child_frame_id_(child_frame_id) {
    setHeader(msg_.header, stamp_s, frame_id_);
    msg_.child_frame_id = const_cast<char*>(child_frame_id_.c_str());
    const Eigen::Vector3d t = T_frame_child.translation();
    const Eigen::Quaterniond q(T_frame_child.rotation());
    msg_.pose.pose.position = {t.x(), t.y(), t.z()};
    msg_.pose.pose.orientation = {q.x(), q.y(), q.z(), q.w()};
}

CloudLayout cloudLayout(const sensor_msgs_msg_dds__PointCloud2_& cloud) {
    CloudLayout layout;
    layout.height = cloud.height;
    layout.width = cloud.width;
    layout.point_step = cloud.point_step;
    layout.row_step = cloud.row_step;
    layout.is_bigendian = cloud.is_bigendian;
    for (uint32_t i = 0; i < cloud.fields._length && cloud.fields._buffer != nullptr; ++i) {
        const auto& f = cloud.fields._buffer[i];
        layout.fields.push_back({f.name ? f.name : "", f.offset, f.datatype, f.count});
    }
    return layout;
}

bool odometryPose(const nav_msgs_msg_dds__Odometry_& odometry, Eigen::Isometry3d& T_frame_child) {
    const auto& p = odometry.pose.pose.position;
    const auto& o = odometry.pose.pose.orientation;
    Eigen::Quaterniond q(o.w, o.x, o.y, o.z);
    const Eigen::Vector3d t(p.x, p.y, p.z);
    if (!t.allFinite() || !q.coeffs().allFinite() || q.norm() < 1e-6) return false;
    T_frame_child = Eigen::Isometry3d::Identity();
    T_frame_child.linear() = q.normalized().toRotationMatrix();
    T_frame_child.translation() = t;
    return true;
}

}  // namespace stairmap::ros2
