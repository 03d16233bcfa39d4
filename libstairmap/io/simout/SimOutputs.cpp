#include "io/simout/SimOutputs.h"

#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace stairmap::io {

void writeTumPoses(std::ostream& out, const StampedPoses& poses) {
    out << "# timestamp tx ty tz qx qy qz qw\n" << std::fixed;
    for (const auto& [stamp, T] : poses) {
        const Eigen::Quaterniond q(T.linear());
        const Eigen::Vector3d t = T.translation();
        out << std::setprecision(6) << stamp << ' ' << std::setprecision(9) << t.x() << ' ' << t.y()
            << ' ' << t.z() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z() << ' ' << q.w() << '\n';
    }
}

void writeTumPosesFile(const std::string& path, const StampedPoses& poses) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    writeTumPoses(out, poses);
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace stairmap::io
