#pragma once
// Parameters of the persistent staircase landmark map (config sections [landmarks] and [floors]).

#include <stdexcept>
#include <string>

#include "core/MergeParams.h"

namespace stairmap {

/// Association, fusion and floor parameters. Defaults relax the paper's Definition 2 (5 cm / 5 cm /
/// 10 deg) a little because landmark detections arrive in the world frame and carry pose drift.
struct LandmarkParams {
    // --- [landmarks] association: two step edges are the "same stair" (Definition 2) when ...
    double match_height_m = 0.06;     ///< [m] ... their heights differ by at most this
    double match_distance_m = 0.08;   ///< [m] ... the perpendicular xy distance between the LINES
                                      ///< (not the centres: partial views shift centres) is at most this
    double match_angle_deg = 10.0;    ///< [deg] ... their xy orientations differ by at most this
    double min_edge_overlap_m = 0.05; ///< [m] ... and they overlap along the edge by at least this
                                      ///< (keeps side-by-side flights with collinear edges apart)
    double heading_tolerance_deg = 30.0;  ///< [deg] uphill headings must agree within this to associate
    // --- [landmarks] footprint association (used when no step matches, e.g. larger pose drift)
    bool use_footprint = true;             ///< also associate staircases whose footprints overlap
    double footprint_min_overlap = 0.3;    ///< [-] xy overlap area / smaller footprint area
    double footprint_min_z_overlap_m = 0.10;  ///< [m] their height ranges must overlap by this
    /// Two partial views of one flight with no common step (one seen from the bottom, one from
    /// the top) are joined when one continues the other: same rise/run (within 15 %), heading and
    /// lateral extent, and the upper one's lowest edge lies where the lower one's edges,
    /// extrapolated by whole steps, predict it (gates widened by 1 cm / 0.5 cm per step).
    int max_extrapolated_steps = 12;  ///< [-] most unseen steps between them; 0 disables
    // --- [landmarks] fusion and confirmation
    double endpoint_tolerance_m = 0.10;  ///< [m] edge ends closer than this are averaged; a new end
                                         ///< farther out extends the edge (partial views). Keep it
                                         ///< above ~4x the end point noise or outliers widen edges
    int confirm_observations = 3;        ///< [-] K: a landmark is confirmed once seen this many times
    /// [-] ...and once its fused flight has this many edges. Single detections may be partial (the
    /// mapping presets accept 3 nosings), but a 1-2 step stage or a curb never grows to 4.
    int confirm_min_steps = 4;
    /// Lower bounds on a fused edge's uncertainty, so that a landmark seen many times can still
    /// follow later (better) detections instead of freezing.
    double fusion_min_sigma_m = 0.003;    ///< [m] perpendicular position of an edge
    double fusion_min_sigma_deg = 0.2;    ///< [deg] edge orientation
    // --- [floors]
    double floor_merge_tolerance_m = 0.40;  ///< [m] heights within this belong to the same floor
    int floor_min_robot_samples = 5;   ///< [-] robot floor samples before a floor is reported
                                       ///< (samples taken while climbing stay below this)
    // --- [floors] linking a flight to the floors the robot climbed between through it
    double traversal_margin_m = 0.30;     ///< [m] slack around the flight's corridor and height range
    double traversal_height_tolerance_m = 0.30;  ///< [m] climb sample height vs the flight's there
    double traversal_min_fraction = 0.6;  ///< [-] share of the climb samples that must be on the flight
    double max_flight_rise_m = 3.7;       ///< [m] most rise of one flight (IBC 1011.8: 12 ft);
                                          ///< a climb over more went through a landing
};

/// The core merge's parameters (core/MergeParams.h) as the landmark map uses them: Definition 2
/// with the map's relaxed gates, a positive edge overlap, and its fusion tolerances.
inline MergeParams toMergeParams(const LandmarkParams& p) {
    MergeParams m;
    m.max_height_diff_m = p.match_height_m;
    m.max_distance_m = p.match_distance_m;
    m.max_angle_deg = p.match_angle_deg;
    m.min_edge_overlap_m = p.min_edge_overlap_m;
    m.endpoint_tolerance_m = p.endpoint_tolerance_m;
    m.min_sigma_m = p.fusion_min_sigma_m;
    m.min_sigma_deg = p.fusion_min_sigma_deg;
    return m;
}

/// Throws std::invalid_argument naming the first field that is out of range.
inline void validateLandmarkParams(const LandmarkParams& p) {
    auto require = [](bool ok, const char* field, const char* what) {
        if (!ok) throw std::invalid_argument(std::string("LandmarkParams.") + field + ": " + what);
    };
    require(p.match_height_m > 0 && p.match_height_m < 1, "match_height_m", "must be in (0, 1) m");
    require(p.match_distance_m > 0 && p.match_distance_m < 1, "match_distance_m",
            "must be in (0, 1) m");
    require(p.match_angle_deg > 0 && p.match_angle_deg <= 45, "match_angle_deg",
            "must be in (0, 45] deg");
    require(p.min_edge_overlap_m >= 0 && p.min_edge_overlap_m < 5, "min_edge_overlap_m",
            "must be in [0, 5) m");
    require(p.heading_tolerance_deg > 0 && p.heading_tolerance_deg <= 90, "heading_tolerance_deg",
            "must be in (0, 90] deg");
    require(p.footprint_min_overlap > 0 && p.footprint_min_overlap <= 1, "footprint_min_overlap",
            "must be in (0, 1]");
    require(p.footprint_min_z_overlap_m >= 0 && p.footprint_min_z_overlap_m < 10,
            "footprint_min_z_overlap_m", "must be in [0, 10) m");
    require(p.max_extrapolated_steps >= 0 && p.max_extrapolated_steps <= 100,
            "max_extrapolated_steps", "must be in [0, 100]");
    require(p.endpoint_tolerance_m >= 0 && p.endpoint_tolerance_m < 1, "endpoint_tolerance_m",
            "must be in [0, 1) m");
    require(p.fusion_min_sigma_m > 0 && p.fusion_min_sigma_m < 1, "fusion_min_sigma_m",
            "must be in (0, 1) m");
    require(p.fusion_min_sigma_deg > 0 && p.fusion_min_sigma_deg < 45, "fusion_min_sigma_deg",
            "must be in (0, 45) deg");
    require(p.confirm_observations >= 1 && p.confirm_observations <= 1000, "confirm_observations",
            "must be in [1, 1000]");
    require(p.confirm_min_steps >= 1 && p.confirm_min_steps <= 1000, "confirm_min_steps",
            "must be in [1, 1000]");
    require(p.floor_merge_tolerance_m > 0 && p.floor_merge_tolerance_m < 5,
            "floor_merge_tolerance_m", "must be in (0, 5) m");
    require(p.traversal_margin_m >= 0 && p.traversal_margin_m < 2, "traversal_margin_m",
            "must be in [0, 2) m");
    require(p.traversal_height_tolerance_m > 0 && p.traversal_height_tolerance_m < 2,
            "traversal_height_tolerance_m", "must be in (0, 2) m");
    require(p.traversal_min_fraction > 0 && p.traversal_min_fraction <= 1, "traversal_min_fraction",
            "must be in (0, 1]");
    require(p.max_flight_rise_m > 0 && p.max_flight_rise_m < 20, "max_flight_rise_m",
            "must be in (0, 20) m");
    require(p.floor_min_robot_samples >= 1, "floor_min_robot_samples", "must be >= 1");
}

}  // namespace stairmap
