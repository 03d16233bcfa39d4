#include "sim/Scene.h"

namespace stairmap::sim {

void Scene::add(const Primitive& primitive) {
    primitives_.push_back(primitive);
    bounds_.push_back(boundingBox(primitive));
}

std::optional<double> Scene::castRay(const Ray& ray, double max_range) const {
    const Eigen::Vector3d inv_direction = ray.direction.cwiseInverse();
    std::optional<double> best;
    double t_max = max_range;
    for (std::size_t i = 0; i < primitives_.size(); ++i) {
        if (!bounds_[i].hitBefore(ray, inv_direction, t_max)) continue;
        const auto t = intersect(primitives_[i], ray);
        if (t && *t <= t_max) {
            best = t;
            t_max = *t;
        }
    }
    return best;
}

}  // namespace stairmap::sim
