#include "io/system/InputFile.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace stairmap::io {

std::ifstream openInputFile(const std::string& path, const std::string& what) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw std::runtime_error(path + ": is a directory, not " + what);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open " + what + ": " + std::strerror(errno));
    return in;
}

}  // namespace stairmap::io
