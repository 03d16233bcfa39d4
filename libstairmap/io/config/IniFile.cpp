#include "io/config/IniFile.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace stairmap::io {

std::unique_ptr<mrpt::config::CConfigFile> openIniFile(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw std::runtime_error(path + ": config file does not exist or is not a regular file");
    }
    if (!std::ifstream(path).good()) {
        throw std::runtime_error(path + ": config file cannot be read");
    }
    return std::make_unique<mrpt::config::CConfigFile>(path);
}

}  // namespace stairmap::io
