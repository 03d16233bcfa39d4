#include "io/cloud/CloudFileFormat.h"

#include <algorithm>
#include <cctype>

namespace stairmap::io {

namespace {
bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string lowerCase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

bool isGzippedText(const std::string& lower) {
    return endsWith(lower, ".xyz.gz") || endsWith(lower, ".pcd.gz") || endsWith(lower, ".ply.gz");
}
}  // namespace

bool isGzippedCloudPath(const std::string& path) { return isGzippedText(lowerCase(path)); }

CloudFileFormat cloudFileFormatOf(const std::string& path) {
    std::string lower = lowerCase(path);
    if (isGzippedText(lower)) lower.resize(lower.size() - 3);  // "x.pcd.gz" -> "x.pcd"
    if (endsWith(lower, ".xyz")) return CloudFileFormat::Xyz;
    if (endsWith(lower, ".pcd")) return CloudFileFormat::Pcd;
    if (endsWith(lower, ".ply")) return CloudFileFormat::Ply;
    if (endsWith(lower, ".rawlog") || endsWith(lower, ".rawlog.gz")) return CloudFileFormat::Rawlog;
    return CloudFileFormat::Unknown;
}

}  // namespace stairmap::io
