// Stream and file helpers of io/LandmarkJson.h: atomic save (temp + fsync + rename), validating load.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/LandmarkJson.h"

namespace stairmap::io {
namespace {

std::string errnoText() { return std::strerror(errno); }

std::string directoryOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

/// Writes all bytes to fd and fsyncs it; returns an error text or "" on success.
std::string writeAndSync(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return "write failed: " + errnoText();
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) return "fsync failed: " + errnoText();
    return "";
}

void syncDirectory(const std::string& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;  // best effort: the rename itself already happened
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

void writeLandmarkState(std::ostream& out, const LandmarkMapState& state,
                        const LandmarkParams& params) {
    out << landmarkStateToJson(state, params).dump(2) << '\n';
    out.flush();
    if (!out) throw std::runtime_error("landmark map: stream write failed");
}

LandmarkMapState readLandmarkState(std::istream& in, const std::string& source_name,
                                   LandmarkParams* params_out) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(source_name + ": not a valid JSON document (corrupt or truncated): " +
                                 e.what());
    }
    try {
        return landmarkStateFromJson(doc, params_out);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(source_name + ": " + e.what());
    }
}

void saveLandmarkStateAtomic(const std::string& path, const LandmarkMapState& state,
                             const LandmarkParams& params) {
    std::ostringstream text;
    writeLandmarkState(text, state, params);
    // One fixed temp name: a temp file left by a killed run is simply overwritten next time.
    const std::string tmp = path + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) {
        throw std::runtime_error(path + ": cannot create temporary file " + tmp + ": " +
                                 errnoText());
    }
    std::string error = writeAndSync(fd, text.str());
    if (::close(fd) != 0 && error.empty()) error = "close failed: " + errnoText();
    if (error.empty() && ::rename(tmp.c_str(), path.c_str()) != 0) {
        error = "rename of " + tmp + " failed: " + errnoText();
    }
    if (!error.empty()) {
        ::unlink(tmp.c_str());
        throw std::runtime_error(path + ": " + error + " (previous file left unchanged)");
    }
    syncDirectory(directoryOf(path));
}

LandmarkMapState loadLandmarkState(const std::string& path, LandmarkParams* params_out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open: " + errnoText());
    return readLandmarkState(in, path, params_out);
}

}  // namespace stairmap::io
