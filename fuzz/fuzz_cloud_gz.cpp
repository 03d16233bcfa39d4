// Fuzz target: readCloudFile on gzipped clouds (.pcd.gz / .ply.gz / .xyz.gz, chosen by the first
// byte), i.e. the gzip member check, the decompression limits and the parser behind them.
#include <stdexcept>

#include "FuzzInput.h"
#include "io/cloud/CloudFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    static const char* const kExtensions[] = {".pcd.gz", ".ply.gz", ".xyz.gz"};
    const std::string path = stairmap::fuzz::asFile(data + 1, size - 1, kExtensions[data[0] % 3]);
    try {
        const stairmap::PointCloud cloud = stairmap::io::readCloudFile(path);
        for (const auto& p : cloud) {
            if (!p.allFinite()) __builtin_trap();
        }
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    return 0;
}
