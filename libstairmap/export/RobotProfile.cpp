#include "export/RobotProfile.h"

#include <cmath>
#include <stdexcept>

namespace stairmap::exporting {
namespace {

void require(bool ok, const char* field, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("RobotProfile.") + field + ": " + what);
}

}  // namespace

void validateRobotProfile(const RobotProfile& p) {
    const auto finite = [](double v) { return std::isfinite(v); };
    require(finite(p.max_rise_m) && p.max_rise_m > 0.0, "max_rise_m", "must be > 0");
    require(finite(p.min_run_m) && p.min_run_m >= 0.0, "min_run_m", "must be >= 0");
    require(finite(p.min_width_m) && p.min_width_m >= 0.0, "min_width_m", "must be >= 0");
    require(finite(p.max_slope_deg) && p.max_slope_deg > 0.0 && p.max_slope_deg < 90.0,
            "max_slope_deg", "must be in (0, 90) deg");
    require(p.max_steps_without_landing >= 1, "max_steps_without_landing", "must be >= 1");
    require(finite(p.footprint_length_m) && p.footprint_length_m > 0.0, "footprint_length_m",
            "must be > 0");
    require(finite(p.footprint_width_m) && p.footprint_width_m > 0.0, "footprint_width_m",
            "must be > 0");
    require(finite(p.clearance_m) && p.clearance_m >= 0.0, "clearance_m", "must be >= 0");
    require(finite(p.height_m) && p.height_m > 0.0, "height_m", "must be > 0");
}

}  // namespace stairmap::exporting
