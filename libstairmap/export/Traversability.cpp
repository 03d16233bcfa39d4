#include "export/Traversability.h"

#include <cstdio>

namespace stairmap::exporting {
namespace {

// Limits are compared with a small slack so that a flight measured exactly at a limit (up to
// floating-point rounding of the degree/radian conversion) passes.
constexpr double kSlack = 1e-9;

std::string format(const char* pattern, double a, double b) {
    char text[96];
    std::snprintf(text, sizeof(text), pattern, a, b);
    return text;
}

}  // namespace

Verdict judgeFlight(const FlightGeometry& f, const RobotProfile& p, Travel travel) {
    Verdict v;
    if (travel == Travel::Up && !p.can_ascend) v.refuse("cannot climb stairs up");
    if (travel == Travel::Down && !p.can_descend) v.refuse("cannot go down stairs");
    if (f.rise_m > p.max_rise_m + kSlack)
        v.refuse(format("rise %.3f > %.3f m", f.rise_m, p.max_rise_m));
    if (f.run_m < p.min_run_m - kSlack) v.refuse(format("run %.3f < %.3f m", f.run_m, p.min_run_m));
    if (f.width_m < p.min_width_m - kSlack) {
        v.refuse(format("width %.2f < %.2f m", f.width_m, p.min_width_m));
    }
    if (f.slope_deg > p.max_slope_deg + kSlack) {
        v.refuse(format("slope %.1f > %.1f deg", f.slope_deg, p.max_slope_deg));
    }
    if (f.max_risers_between_landings > p.max_steps_without_landing) {
        v.refuse(format("%.0f risers without a landing > %.0f", f.max_risers_between_landings,
                        p.max_steps_without_landing));
    }
    return v;
}

}  // namespace stairmap::exporting
