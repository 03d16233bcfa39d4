// Fuzz target: the point-cloud stream readers (XYZ, PCD, PLY). The first byte picks the reader,
// the rest is the file. Any input must either parse into finite points or throw.
#include <sstream>
#include <stdexcept>

#include "FuzzInput.h"
#include "io/cloud/CloudFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    std::istringstream in(stairmap::fuzz::asString(data + 1, size - 1), std::ios::binary);
    try {
        stairmap::PointCloud cloud;
        switch (data[0] % 3) {
            case 0: cloud = stairmap::io::readXyz(in); break;
            case 1: cloud = stairmap::io::readPcd(in); break;
            default: cloud = stairmap::io::readPly(in); break;
        }
        for (const auto& p : cloud) {
            if (!p.allFinite()) __builtin_trap();  // readers drop or reject non-finite points
        }
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    return 0;
}
