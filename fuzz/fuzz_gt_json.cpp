// Fuzz target: the simulator's ground truth (gt.json) as `stairmap eval --gt` reads it.
#include <stdexcept>

#include "FuzzInput.h"
#include "io/json/GroundTruthJson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = stairmap::fuzz::asFile(data, size, ".json");
    try {
        (void)stairmap::io::readGroundTruthFile(path);
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    return 0;
}
