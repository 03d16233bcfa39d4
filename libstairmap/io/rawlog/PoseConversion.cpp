#include "io/rawlog/PoseConversion.h"

#include <mrpt/math/CMatrixFixed.h>

namespace stairmap::io {

Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& pose) {
    const auto H = pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) T.linear()(r, c) = H(r, c);
        T.translation()(r) = H(r, 3);
    }
    return T;
}

mrpt::poses::CPose3D toCPose3D(const Eigen::Isometry3d& T) {
    mrpt::math::CMatrixDouble33 R;
    mrpt::math::CVectorFixedDouble<3> t;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) R(r, c) = T.linear()(r, c);
        t[r] = T.translation()(r);
    }
    return mrpt::poses::CPose3D::FromRotationAndTranslation(R, t);
}

}  // namespace stairmap::io
