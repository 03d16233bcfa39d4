#pragma once
// A simulated world: solid primitives plus the ground truth of what they represent.

#include <optional>
#include <string>
#include <vector>

#include "core/GroundTruth.h"
#include "sim/Primitives.h"

namespace stairmap::sim {

class Scene {
public:
    /// Adds a solid; its bounding box is cached for culling.
    void add(const Primitive& primitive);

    /// Distance [m] to the nearest surface along `ray` within max_range, or nullopt.
    /// Cost: one slab test per primitive plus exact tests for the boxes the ray enters.
    std::optional<double> castRay(const Ray& ray, double max_range) const;

    const std::vector<Primitive>& primitives() const { return primitives_; }
    SceneTruth& truth() { return truth_; }
    const SceneTruth& truth() const { return truth_; }

    std::string name;  ///< e.g. "two_floor"

private:
    std::vector<Primitive> primitives_;
    std::vector<Aabb> bounds_;
    SceneTruth truth_;
};

}  // namespace stairmap::sim
