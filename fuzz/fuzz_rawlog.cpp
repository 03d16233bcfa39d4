// Fuzz target: a rawlog through the scan source (as `stairmap map` reads it, including the
// per-object allocation cap) and through readRawlogCloud (as `stairmap detect` reads it).
#include <stdexcept>

#include "FuzzInput.h"
#include "io/rawlog/RawlogCloud.h"
#include "io/rawlog/RawlogScanSource.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = stairmap::fuzz::asFile(data, size, ".rawlog");
    try {
        stairmap::io::RawlogScanSource source(path);
        while (auto scan = source.next()) {
            for (const auto& p : scan->points_robot) {
                if (!p.allFinite()) __builtin_trap();
            }
        }
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    try {
        (void)stairmap::io::readRawlogCloud(path);
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    return 0;
}
