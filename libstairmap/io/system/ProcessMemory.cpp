#include "io/system/ProcessMemory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace stairmap::io {
namespace {

std::size_t statusFieldBytes(const std::string& field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind(field + ":", 0) != 0) continue;
        std::istringstream value(line.substr(field.size() + 1));
        std::size_t kib = 0;
        value >> kib;
        return kib * 1024;
    }
    return 0;
}

}  // namespace

std::size_t peakRssBytes() { return statusFieldBytes("VmHWM"); }
std::size_t currentRssBytes() { return statusFieldBytes("VmRSS"); }

}  // namespace stairmap::io
