// XYZ: one point per line, "x y z" in ASCII; extra columns (intensity, colour...) are ignored.

#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileParsing.h"

namespace stairmap::io {

namespace {

/// Strips a '#' comment; returns the words left on the line.
std::vector<std::string_view> dataWords(const std::string& line) {
    std::string_view view(line);
    const std::size_t hash = view.find('#');
    if (hash != std::string_view::npos) view = view.substr(0, hash);
    return detail::splitWords(view);
}

}  // namespace

PointCloud readXyz(std::istream& in) {
    detail::PointCollector points;
    std::string line;
    std::size_t line_number = 0;
    while (detail::readLine(in, line)) {
        ++line_number;
        const auto words = dataWords(line);
        if (words.empty()) continue;
        if (words.size() < 3) {
            throw std::runtime_error("line " + std::to_string(line_number) +
                                     ": expected at least 3 numbers (x y z), found " +
                                     std::to_string(words.size()) + " column(s)");
        }
        double xyz[3];
        for (int k = 0; k < 3; ++k) {
            if (!detail::parseNumber(words[k], xyz[k])) {
                throw std::runtime_error("line " + std::to_string(line_number) + ": '" +
                                         std::string(words[k].substr(0, 40)) + "' is not a number");
            }
        }
        points.add(xyz[0], xyz[1], xyz[2]);
    }
    if (in.bad()) throw std::runtime_error("read error");
    return points.finish();
}

void writeXyz(std::ostream& out, const PointCloud& cloud) {
    // The comment line keeps an empty cloud from becoming a zero-byte file (which reads as an error).
    out << "# x y z [m], written by stairmap\n";
    for (const Eigen::Vector3f& p : cloud) detail::writeAsciiPoint(out, p);
    detail::checkWritten(out);
}

}  // namespace stairmap::io
