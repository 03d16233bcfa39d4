// Stream and file helpers of io/json/LandmarkJson.h: atomic save (io/system/AtomicFile.h), validating load.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/system/AtomicFile.h"
#include "io/system/InputFile.h"
#include "io/json/LandmarkJson.h"

namespace stairmap::io {

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
    writeTextFileAtomic(path, text.str());
}

LandmarkMapState loadLandmarkState(const std::string& path, LandmarkParams* params_out) {
    std::ifstream in = openInputFile(path, "a landmarks.json file");
    return readLandmarkState(in, path, params_out);
}

}  // namespace stairmap::io
