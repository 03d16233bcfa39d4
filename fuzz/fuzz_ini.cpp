// Fuzz target: INI files through every loader a user's config reaches: the mapper's parameters
// (with [detector] and [landmarks]) and the simulator's scene files.
#include <stdexcept>

#include "FuzzInput.h"
#include "io/config/MapperConfig.h"
#include "io/config/SceneIni.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = stairmap::fuzz::asFile(data, size, ".ini");
    try {
        (void)stairmap::io::loadMapperParams(path);
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    try {
        (void)stairmap::io::loadSimulationConfig(path);
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    return 0;
}
