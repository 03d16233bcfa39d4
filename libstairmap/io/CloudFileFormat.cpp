#include "io/CloudFileFormat.h"

#include <algorithm>
#include <cctype>

namespace stairmap::io {

namespace {
bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

CloudFileFormat cloudFileFormatOf(const std::string& path) {
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (endsWith(lower, ".xyz")) return CloudFileFormat::Xyz;
    if (endsWith(lower, ".pcd")) return CloudFileFormat::Pcd;
    if (endsWith(lower, ".ply")) return CloudFileFormat::Ply;
    if (endsWith(lower, ".rawlog") || endsWith(lower, ".rawlog.gz")) return CloudFileFormat::Rawlog;
    return CloudFileFormat::Unknown;
}

}  // namespace stairmap::io
