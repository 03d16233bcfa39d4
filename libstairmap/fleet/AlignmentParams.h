#pragma once
// Parameters of the map alignment (fleet/MapAlignment.h). Lengths [m], angles [deg].

#include <stdexcept>
#include <string>

namespace stairmap::fleet {

struct AlignmentParams {
    // --- candidate pairs: two landmarks may be one flight when their shapes agree
    double rise_tolerance_m = 0.01;     ///< [m] |rise_a - rise_b| (or 5 % of the rise, if larger)
    double run_tolerance_m = 0.03;      ///< [m] |run_a - run_b| (or 10 % of the run, if larger)
    double width_tolerance_m = 0.30;    ///< [m] |width_a - width_b| (partial edges read short)
    double turn_tolerance_deg = 5.0;    ///< [deg] mean turn per step (0 straight, spirals turn)
    int min_overlap_steps = 1;          ///< [-] nosings a hypothesis must pair within one flight
    // --- a step of one map lies on a step of the other (after the transform) when ...
    double match_height_m = 0.06;       ///< [m] ... heights differ by at most this
    double match_distance_m = 0.10;     ///< [m] ... its centre is this close to the other's line
    double match_angle_deg = 10.0;      ///< [deg] ... and the edge directions agree within this
    // --- least squares: a-priori sigmas of one matched nosing pair
    double sigma_perp_m = 0.02;         ///< [m] across the nosing line (well measured)
    double sigma_lateral_m = 0.10;      ///< [m] along the nosing (partial views shift the centre)
    double sigma_angle_deg = 2.0;       ///< [deg] edge direction
    // --- ambiguity: two hypotheses are different transforms when they differ by more than ...
    double distinct_translation_m = 0.15;  ///< [m] ... this in x, y or z
    double distinct_yaw_deg = 5.0;         ///< [deg] ... or this in yaw

    /// Throws std::invalid_argument naming the first field out of range.
    void validate() const {
        auto require = [](bool ok, const char* field) {
            if (!ok) throw std::invalid_argument(std::string("AlignmentParams.") + field +
                                                 ": out of range");
        };
        require(rise_tolerance_m > 0 && rise_tolerance_m < 0.5, "rise_tolerance_m");
        require(run_tolerance_m > 0 && run_tolerance_m < 1, "run_tolerance_m");
        require(width_tolerance_m > 0 && width_tolerance_m < 5, "width_tolerance_m");
        require(turn_tolerance_deg > 0 && turn_tolerance_deg < 90, "turn_tolerance_deg");
        require(min_overlap_steps >= 1 && min_overlap_steps < 100, "min_overlap_steps");
        require(match_height_m > 0 && match_height_m < 0.5, "match_height_m");
        require(match_distance_m > 0 && match_distance_m < 1, "match_distance_m");
        require(match_angle_deg > 0 && match_angle_deg < 45, "match_angle_deg");
        require(sigma_perp_m > 0 && sigma_lateral_m > 0 && sigma_angle_deg > 0, "sigma_*");
        require(distinct_translation_m > 0 && distinct_yaw_deg > 0, "distinct_*");
    }
};

}  // namespace stairmap::fleet
