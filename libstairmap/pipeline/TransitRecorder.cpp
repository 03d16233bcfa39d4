#include "pipeline/TransitRecorder.h"

#include <cmath>
#include <stdexcept>

namespace stairmap::pipeline {

TransitRecorder::TransitRecorder(double min_height_change_m, double sample_spacing_m,
                                 std::size_t max_samples)
    : min_height_change_m_(min_height_change_m),
      sample_spacing_m_(sample_spacing_m),
      max_samples_(max_samples) {
    if (!(min_height_change_m_ > 0) || !(sample_spacing_m_ >= 0) || max_samples_ < 3) {
        throw std::invalid_argument("TransitRecorder: height change must be > 0, spacing >= 0, "
                                    "at least 3 samples");
    }
}

std::optional<FloorTransit> TransitRecorder::update(const Eigen::Vector3d& floor_position,
                                                    bool level, double stamp_s) {
    if (!floor_position.allFinite()) return std::nullopt;
    if (!level) {
        if (path_.empty()) path_.push_back(last_level_.value_or(floor_position));
        addClimbSample(floor_position);
        return std::nullopt;
    }
    last_level_ = floor_position;
    if (path_.empty()) return std::nullopt;
    path_.push_back(floor_position);
    std::optional<FloorTransit> out;
    const double change = std::abs(path_.back().z() - path_.front().z());
    if (path_.size() >= 3 && change > min_height_change_m_) out = FloorTransit{path_, stamp_s};
    path_.clear();
    return out;
}

void TransitRecorder::addClimbSample(const Eigen::Vector3d& floor_position) {
    if (path_.size() >= 2 && (floor_position - path_.back()).norm() < sample_spacing_m_) return;
    path_.push_back(floor_position);
    if (path_.size() <= max_samples_) return;
    // Thin out: keep every other sample, always the first (on level ground) and the newest.
    std::vector<Eigen::Vector3d> thinned;
    for (std::size_t i = 0; i + 1 < path_.size(); i += 2) thinned.push_back(path_[i]);
    thinned.push_back(path_.back());
    path_ = std::move(thinned);
}

}  // namespace stairmap::pipeline
