#include "viz/MapOverview.h"

#include <mrpt/img/CImage.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stairmap::viz {
using map::VoxelMap;
namespace {

using mrpt::img::TColor;

/// A pixel coordinate computed in double, clamped to +-1e6 before the conversion to int: far or
/// non-finite world coordinates (an extent that overflows to infinity gives 0 * inf = NaN) then
/// land off the image, where drawing clips them, instead of overflowing int.
int toPixel(double v) {
    constexpr double kFar = 1e6;
    if (!(v > -kFar)) return -static_cast<int>(kFar);  // also NaN
    return static_cast<int>(std::min(v, kFar));
}

/// World (a, b) -> pixel mapping of one panel: a to the right, b up; same scale on both axes.
struct PanelProjection {
    int x0 = 0, y0 = 0, size = 0;
    double a_min = 0, b_min = 0, scale = 1;

    int px(double a) const { return toPixel(x0 + 10 + std::floor((a - a_min) * scale)); }
    int py(double b) const { return toPixel(y0 + size - 10 - std::floor((b - b_min) * scale)); }
};

struct Bounds {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e18), hi = Eigen::Vector3d::Constant(-1e18);
    void add(const Eigen::Vector3d& p) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
    bool valid() const { return (hi - lo).minCoeff() >= 0; }
};

PanelProjection panel(int index, int size, double a_min, double a_max, double b_min, double b_max) {
    PanelProjection p;
    p.x0 = index * size;
    p.y0 = 20;
    p.size = size;
    p.a_min = a_min;
    p.b_min = b_min;
    const double span = std::max({a_max - a_min, b_max - b_min, 1.0});
    p.scale = (size - 20) / span;
    return p;
}

TColor heightColour(double z, double z_min, double z_max) {
    const double t = std::clamp((z - z_min) / std::max(z_max - z_min, 1e-3), 0.0, 1.0);
    const auto g = static_cast<uint8_t>(200 - 150 * t);
    return TColor(g, g, static_cast<uint8_t>(g + 40 * (1 - t)));
}

void drawStaircase(mrpt::img::CImage& img, const PanelProjection& p, const StaircaseLandmark& s,
                   bool side_view) {
    const TColor red(220, 30, 30);
    for (const StairEdge& e : s.stairs.steps) {
        if (side_view) {
            img.drawCircle(p.px(e.centre().x()), p.py(e.centre().z()), 2, red, 2);
        } else {
            img.line(p.px(e.start.x()), p.py(e.start.y()), p.px(e.end.x()), p.py(e.end.y()), red, 2);
        }
    }
    const Eigen::Vector3d& loc = s.stairs.location;
    const int lx = p.px(loc.x());
    const int ly = side_view ? p.py(loc.z()) : p.py(loc.y());
    img.textOut(lx + 4, ly - 14, "#" + std::to_string(s.id), red);
}

struct Panels {
    std::vector<std::pair<double, double>> z_bands;  ///< top views
    std::vector<std::string> titles;
};

Panels topViewBands(const MapView& view, const OverviewParams& params) {
    Panels panels;
    if (view.floors.empty()) {
        panels.z_bands.push_back({-1e18, 1e18});
        panels.titles.push_back("top view (all heights)");
    }
    for (const Floor& f : view.floors) {
        panels.z_bands.push_back({f.z - params.floor_band_below_m, f.z + params.floor_band_above_m});
        char title[80];
        std::snprintf(title, sizeof(title), "floor %d (z = %.2f m), top view", f.id, f.z);
        panels.titles.push_back(title);
    }
    return panels;
}

bool stairTouchesBand(const StaircaseLandmark& s, std::pair<double, double> band) {
    if (s.stairs.steps.empty()) return false;
    const double z_lo = s.stairs.steps.front().centre().z() - s.stairs.step_height;
    const double z_hi = s.stairs.steps.back().centre().z();
    return z_hi >= band.first && z_lo <= band.second;
}

Bounds mapBounds(const PointCloud& voxels, const MapView& view) {
    Bounds b;
    for (const auto& v : voxels) b.add(v.cast<double>());
    for (const auto& t : view.trajectory) b.add(t);
    for (const auto& s : view.staircases) {
        for (const auto& e : s.stairs.steps) {
            b.add(e.start);
            b.add(e.end);
        }
    }
    if (!b.valid()) b.add(Eigen::Vector3d::Zero());
    return b;
}

/// One panel: voxels within the height band (grey by height), trajectory (blue), staircases (red).
void drawPanel(mrpt::img::CImage& img, const PanelProjection& p, std::pair<double, double> band,
               bool side, const PointCloud& voxels, const MapView& view, const Bounds& b) {
    img.rectangle(p.x0, p.y0, p.x0 + p.size - 1, p.y0 + p.size - 1, TColor(120, 120, 120));
    auto vertical = [&](const auto& q) { return side ? p.py(q.z()) : p.py(q.y()); };
    for (const auto& v : voxels) {
        if (v.z() < band.first || v.z() > band.second) continue;
        const int x = p.px(v.x()), y = vertical(v);
        img.filledRectangle(x, y, x, y, heightColour(v.z(), b.lo.z(), b.hi.z()));
    }
    for (std::size_t k = 1; k < view.trajectory.size(); ++k) {
        const auto& a = view.trajectory[k - 1];
        const auto& c = view.trajectory[k];
        if (!side && (a.z() < band.first || a.z() > band.second)) continue;
        img.line(p.px(a.x()), vertical(a), p.px(c.x()), vertical(c), TColor(40, 90, 230), 1);
    }
    for (const auto& s : view.staircases) {
        if (side || stairTouchesBand(s, band)) drawStaircase(img, p, s, side);
    }
}

}  // namespace

void saveMapOverview(const MapView& view, const std::string& path, const OverviewParams& params) {
    const PointCloud voxels = view.voxels ? view.voxels->occupiedVoxelCentres() : PointCloud{};
    const Bounds b = mapBounds(voxels, view);
    const Panels panels = topViewBands(view, params);
    const int n = static_cast<int>(panels.z_bands.size()) + 1;
    const int size = params.panel_px;
    mrpt::img::CImage img(n * size, size + 20, mrpt::img::CH_RGB);
    img.filledRectangle(0, 0, n * size - 1, size + 19, TColor(255, 255, 255));
    for (int i = 0; i < n; ++i) {
        const bool side = i == n - 1;
        const PanelProjection p = side ? panel(i, size, b.lo.x(), b.hi.x(), b.lo.z(), b.hi.z())
                                       : panel(i, size, b.lo.x(), b.hi.x(), b.lo.y(), b.hi.y());
        img.textOut(p.x0 + 6, 2, side ? "side view (x-z)" : panels.titles[i], TColor(0, 0, 0));
        drawPanel(img, p, side ? std::make_pair(-1e18, 1e18) : panels.z_bands[i], side, voxels,
                  view, b);
    }
    if (!img.saveToFile(path)) throw std::runtime_error(path + ": writing the PNG failed");
}

}  // namespace stairmap::viz
