#include "io/config/DetectorConfig.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace stairmap::io {
namespace {

std::string trimmed(std::string s) {
    // MRPT keeps trailing comments out, but not surrounding blanks.
    const auto not_space = [](unsigned char c) { return !std::isspace(c); };
    s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
    s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
    return s;
}

class SectionReader {
public:
    SectionReader(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
        : cfg_(cfg), section_(section) {}

    void number(const char* key, double& value) const {
        if (const auto text = raw(key)) value = parseNumber(key, *text);
    }
    void integer(const char* key, int& value) const {
        if (const auto text = raw(key)) {
            const double v = parseNumber(key, *text);
            if (v != std::floor(v) || std::abs(v) > 1e9) fail(key, *text, "is not an integer");
            value = static_cast<int>(v);
        }
    }
    void boolean(const char* key, bool& value) const {
        const auto text = raw(key);
        if (!text) return;
        std::string t = *text;
        std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
        if (t == "true" || t == "1" || t == "yes") value = true;
        else if (t == "false" || t == "0" || t == "no") value = false;
        else fail(key, *text, "is not a boolean (true/false)");
    }
    std::optional<double> optionalNumber(const char* key) const {
        if (const auto text = raw(key)) return parseNumber(key, *text);
        return std::nullopt;
    }
    [[noreturn]] void fail(const char* key, const std::string& text, const char* what) const {
        throw std::invalid_argument("[" + section_ + "] " + key + " = '" + text + "' " + what);
    }

private:
    std::optional<std::string> raw(const char* key) const {
        // Read before asking whether the key exists: a KeyRecorder (IniKeys.h) learns the key.
        std::string text = cfg_.read_string(section_, key, "");
        if (!cfg_.keyExists(section_, key)) return std::nullopt;
        return trimmed(std::move(text));
    }
    double parseNumber(const char* key, const std::string& text) const {
        std::size_t used = 0;
        double v = 0.0;
        try {
            v = std::stod(text, &used);
        } catch (const std::exception&) {
            fail(key, text, "is not a number");
        }
        if (used != text.size()) fail(key, text, "is not a number");
        if (!std::isfinite(v)) fail(key, text, "is not finite");
        return v;
    }

    const mrpt::config::CConfigFileBase& cfg_;
    std::string section_;
};

void readPreprocessing(const SectionReader& r, DetectorParams& p) {
    r.number("leaf_size_m", p.leaf_size_m);
    r.number("max_range_m", p.max_range_m);
    r.number("max_height_above_floor_m", p.max_height_above_floor_m);
    r.number("max_depth_below_floor_m", p.max_depth_below_floor_m);
    r.number("row_height_m", p.row_height_m);
    r.number("tilted_ring_row_height_m", p.tilted_ring_row_height_m);
    r.integer("azimuth_bins", p.azimuth_bins);
    r.number("edge_min_dz_m", p.edge_min_dz_m);
    r.number("edge_spill_dz_m", p.edge_spill_dz_m);
    r.number("neighbour_walk_m", p.neighbour_walk_m);
}

void readSegmentation(const SectionReader& r, DetectorParams& p) {
    r.number("split_distance_m", p.split_distance_m);
    r.number("split_noise_factor", p.split_noise_factor);
    r.number("max_split_distance_m", p.max_split_distance_m);
    r.integer("min_line_points", p.min_line_points);
    r.number("min_line_length_m", p.min_line_length_m);
    r.number("max_point_gap_m", p.max_point_gap_m);
    r.number("dashed_nosing_gap_m", p.dashed_nosing_gap_m);
    r.integer("sparse_line_points", p.sparse_line_points);
    r.integer("few_level_spiral_levels", p.few_level_spiral_levels);
    r.number("tread_spiral_cell_m", p.tread_spiral_cell_m);
    r.number("tread_spiral_window_m", p.tread_spiral_window_m);
    r.number("point_sigma_m", p.point_sigma_m);
    r.number("merge_chi2", p.merge_chi2);
    r.number("vertical_merge_dz_m", p.vertical_merge_dz_m);
    r.number("vertical_merge_dist_m", p.vertical_merge_dist_m);
    r.number("max_collinear_gap_m", p.max_collinear_gap_m);
    r.number("floor_tolerance_m", p.floor_tolerance_m);
    r.number("floor_refine_window_m", p.floor_refine_window_m);
    r.number("floor_search_radius_m", p.floor_search_radius_m);
}

void readDetection(const SectionReader& r, DetectorParams& p) {
    r.number("min_step_height_m", p.min_step_height_m);
    r.number("max_step_height_m", p.max_step_height_m);
    r.number("min_step_depth_m", p.min_step_depth_m);
    r.number("max_step_depth_m", p.max_step_depth_m);
    r.number("min_slope_deg", p.min_slope_deg);
    r.number("max_level_tread_depth_m", p.max_level_tread_depth_m);
    r.number("min_level_tread_slope_deg", p.min_level_tread_slope_deg);
    r.number("min_deep_tread_m", p.min_deep_tread_m);
    r.number("max_double_step_rise_m", p.max_double_step_rise_m);
    r.boolean("continue_every_other_step", p.continue_every_other_step);
    r.boolean("continue_by_next_riser", p.continue_by_next_riser);
    r.boolean("ascend_from_below_floor", p.ascend_from_below_floor);
    r.boolean("profile_flights", p.profile_flights);
    r.boolean("level_by_line_spacing", p.level_by_line_spacing);
    r.number("max_ramp_rms_ratio", p.max_ramp_rms_ratio);
    r.number("max_descent_start_off_level", p.max_descent_start_off_level);
    r.number("max_slope_deg", p.max_slope_deg);
    r.number("max_parallel_deg", p.max_parallel_deg);
    r.number("edge_height_tolerance_m", p.edge_height_tolerance_m);
    r.number("between_overlap_ratio", p.between_overlap_ratio);
    r.number("min_overlap_ratio", p.min_overlap_ratio);
    r.number("init_height_factor", p.init_height_factor);
    r.integer("min_steps", p.min_steps);
    r.integer("max_staircases_per_direction", p.max_staircases_per_direction);
    r.boolean("detect_ascending", p.detect_ascending);
    r.boolean("detect_descending", p.detect_descending);
}

}  // namespace

DetectorConfig loadDetectorConfig(const mrpt::config::CConfigFileBase& cfg,
                                  const std::string& section) {
    const SectionReader reader(cfg, section);
    DetectorConfig out;
    readPreprocessing(reader, out.params);
    readSegmentation(reader, out.params);
    readDetection(reader, out.params);
    out.robot_height_m = reader.optionalNumber("robot_height_m");
    if (out.robot_height_m && (*out.robot_height_m < -10.0 || *out.robot_height_m > 10.0)) {
        reader.fail("robot_height_m", std::to_string(*out.robot_height_m),
                    "is out of range [-10, 10] m");
    }
    try {
        out.params.validate();
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("[" + section + "] " + e.what());
    }
    return out;
}

}  // namespace stairmap::io
