#pragma once
// Outputs of `stairmap merge` (docs/merge.md):
//   alignment.json  {"maps":[{"source":PATH,
//                     "T_first_this":{"x":m,"y":m,"z":m,"yaw_deg":deg},
//                     "sigma":{"xy_m":m,"z_m":m,"yaw_deg":deg},
//                     "pairs":[[ID_in_first,ID_in_this],...]}, ...]}
//     one entry per input map in the order given; the first map's entry is the identity; a point
//     p of map k is T_first_this * p in the first map's frame (yaw about +z, then translation).
//   provenance.json {"maps":[PATH,...], "staircases":[{"id":i,
//                     "sources":[{"map":k,"id":i,"observations":n},...],
//                     "steps":[[{"map":k,"observations":n},...], ...]}]}
//     per landmark of the merged landmarks.json: which map's landmark went into it and how often
//     that map saw it; per step (bottom to top) how many observations each map contributed.

#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fleet/MapAlignment.h"
#include "fleet/MapFusion.h"

namespace stairmap::io {

/// One entry of alignment.json.
struct AlignmentRecord {
    std::string source;              ///< the map's path as given
    fleet::Transform4 T_first_this;  ///< p_first = T_first_this * p_this
    fleet::AlignmentSigma sigma;
    std::vector<fleet::LandmarkPair> pairs;  ///< (id in the first map, id in this map)
};

nlohmann::json alignmentToJson(const std::vector<AlignmentRecord>& maps);
/// Validating inverse; throws std::runtime_error "<field>: <problem>".
std::vector<AlignmentRecord> alignmentFromJson(const nlohmann::json& doc);

nlohmann::json provenanceToJson(const std::vector<fleet::LandmarkProvenance>& provenance,
                                const std::vector<std::string>& sources);

/// Atomic file writers (io/system/AtomicFile.h); std::runtime_error names the path.
void saveAlignment(const std::string& path, const std::vector<AlignmentRecord>& maps);
void saveProvenance(const std::string& path,
                    const std::vector<fleet::LandmarkProvenance>& provenance,
                    const std::vector<std::string>& sources);

}  // namespace stairmap::io
