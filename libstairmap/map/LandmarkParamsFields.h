#pragma once
// One table of the LandmarkParams fields, with their config section and key, shared by the INI
// loader and the JSON writer/reader so that the three never drift apart.

#include "map/LandmarkParams.h"

namespace stairmap::map {

/// Calls visit(section, key, field&) for every field; field is double&, int& or bool&.
template <class Params, class Visitor>
void forEachLandmarkParam(Params& p, Visitor&& visit) {
    visit("landmarks", "match_height_m", p.match_height_m);
    visit("landmarks", "match_distance_m", p.match_distance_m);
    visit("landmarks", "match_angle_deg", p.match_angle_deg);
    visit("landmarks", "min_edge_overlap_m", p.min_edge_overlap_m);
    visit("landmarks", "heading_tolerance_deg", p.heading_tolerance_deg);
    visit("landmarks", "use_footprint", p.use_footprint);
    visit("landmarks", "footprint_min_overlap", p.footprint_min_overlap);
    visit("landmarks", "footprint_min_z_overlap_m", p.footprint_min_z_overlap_m);
    visit("landmarks", "max_extrapolated_steps", p.max_extrapolated_steps);
    visit("landmarks", "endpoint_tolerance_m", p.endpoint_tolerance_m);
    visit("landmarks", "confirm_observations", p.confirm_observations);
    visit("landmarks", "confirm_min_steps", p.confirm_min_steps);
    visit("landmarks", "fusion_min_sigma_m", p.fusion_min_sigma_m);
    visit("landmarks", "fusion_min_sigma_deg", p.fusion_min_sigma_deg);
    visit("floors", "floor_merge_tolerance_m", p.floor_merge_tolerance_m);
    visit("floors", "floor_min_robot_samples", p.floor_min_robot_samples);
    visit("floors", "traversal_margin_m", p.traversal_margin_m);
    visit("floors", "traversal_height_tolerance_m", p.traversal_height_tolerance_m);
    visit("floors", "traversal_min_fraction", p.traversal_min_fraction);
    visit("floors", "max_flight_rise_m", p.max_flight_rise_m);
}

}  // namespace stairmap::map
