#pragma once
// Can this robot take this flight, up or down? Each limit of the profile is checked on its own so
// that a refusal lists every reason ("rise 0.190 > 0.180 m"). A value exactly at a limit passes.

#include <string>
#include <vector>

#include "export/FlightGeometry.h"
#include "export/RobotProfile.h"

namespace stairmap::exporting {

enum class Travel { Up, Down };

inline const char* travelName(Travel t) { return t == Travel::Up ? "up" : "down"; }

struct Verdict {
    bool traversable = true;
    std::vector<std::string> reasons;  ///< why not (empty when traversable)

    void refuse(std::string reason) {
        traversable = false;
        reasons.push_back(std::move(reason));
    }
};

/// Checks direction permission, rise, run, width, slope and risers between landings.
Verdict judgeFlight(const FlightGeometry& flight, const RobotProfile& profile, Travel travel);

}  // namespace stairmap::exporting
