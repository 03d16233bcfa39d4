// Fuzz target: landmarks.json as `--map-in` reads it (schema and plausibility checks).
#include <sstream>
#include <stdexcept>

#include "FuzzInput.h"
#include "io/json/LandmarkJson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(stairmap::fuzz::asString(data, size));
    try {
        stairmap::LandmarkParams params;
        (void)stairmap::io::readLandmarkState(in, "fuzz.json", &params);
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    return 0;
}
