#include "core/TreadBoundaries.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace stairmap {

namespace {

constexpr float kEmpty = HeightGrid::kEmpty;

/// Mean height and spread of one patch.
struct Patch {
    double sum_z = 0, sum_zz = 0;
    int cells = 0;
    double mean() const { return sum_z / cells; }
    double spread() const { return std::sqrt(std::max(0.0, sum_zz / cells - mean() * mean())); }
};

/// Patches grown over 8-neighbouring cells within max_neighbour_dz_m of the cell and
/// max_patch_dz_m of the patch's mean so far; `label` per cell (-1 empty).
std::vector<Patch> growPatches(const HeightGrid& s, const TreadBoundaryParams& p,
                               std::vector<int>& label) {
    std::vector<Patch> patches;
    label.assign(s.top.size(), -1);
    if (p.floor_band_m > 0) {  // patch 0: the floor
        Patch floor;
        const float lo = static_cast<float>(p.floor_z - p.floor_band_m);
        const float hi = static_cast<float>(p.floor_z + p.floor_band_m);
        for (std::size_t c = 0; c < s.top.size(); ++c) {
            const float z = s.top[c];
            if (z < lo || z > hi) continue;  // empty cells (-inf) too
            label[c] = 0;
            floor.sum_z += z, floor.sum_zz += static_cast<double>(z) * z, ++floor.cells;
        }
        patches.push_back(floor);  // even empty: patch 0 is the floor's (never flat then)
    }
    std::vector<int> stack;
    const int n = s.n;
    const int around[8] = {-n - 1, -n, -n + 1, -1, 1, n - 1, n, n + 1};
    const float step = static_cast<float>(p.max_neighbour_dz_m);
    const float band = static_cast<float>(p.max_patch_dz_m);
    for (int seed = n; seed < static_cast<int>(s.top.size()) - n; ++seed) {
        if (s.top[seed] == kEmpty || label[seed] >= 0) continue;
        const int id = static_cast<int>(patches.size());
        Patch patch;
        label[seed] = id;
        stack.assign(1, seed);
        while (!stack.empty()) {
            const int c = stack.back();
            stack.pop_back();
            const float z = s.top[c];
            patch.sum_z += z, patch.sum_zz += static_cast<double>(z) * z, ++patch.cells;
            const float mean = static_cast<float>(patch.sum_z / patch.cells);
            for (const int d : around) {
                const int m = c + d;  // the border keeps m inside the grid
                const float zm = s.top[m];
                // empty cells (-inf) fail the first test
                if (label[m] >= 0 || !(std::abs(zm - z) <= step) || std::abs(zm - mean) > band)
                    continue;
                label[m] = id;
                stack.push_back(m);
            }
        }
        patches.push_back(patch);
    }
    return patches;
}

/// A boundary midpoint between an upper and a lower patch.
struct BoundaryPoint {
    std::uint64_t pair;  ///< upper patch << 32 | lower patch
    Eigen::Vector2d xy;
};

/// The principal line of `pts` (at least one): its centroid, direction and RMS distance.
struct PrincipalLine {
    Eigen::Vector2d mean, dir;
    double rms = 0.0;
};

PrincipalLine principalLine(const std::vector<Eigen::Vector2d>& pts) {
    PrincipalLine l;
    l.mean = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& q : pts) l.mean += q;
    l.mean /= static_cast<double>(pts.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector2d& q : pts) cov += (q - l.mean) * (q - l.mean).transpose();
    cov /= static_cast<double>(pts.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    l.dir = eig.eigenvectors().col(1);
    l.rms = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
    return l;
}

/// The line through `pts`, if straight and long enough.
bool boundaryLine(const std::vector<Eigen::Vector2d>& pts, double z, const TreadBoundaryParams& p,
                  LineSegment& out) {
    const int count = static_cast<int>(pts.size());
    if (count < p.min_line_cells) return false;
    const PrincipalLine line = principalLine(pts);
    if (line.rms > p.max_line_rms_m) return false;
    double lo = 1e9, hi = -1e9;
    for (const Eigen::Vector2d& q : pts) {
        const double t = (q - line.mean).dot(line.dir);
        lo = std::min(lo, t), hi = std::max(hi, t);
    }
    if (hi - lo < p.min_line_length_m) return false;
    out.start = line.mean + lo * line.dir;
    out.end = line.mean + hi * line.dir;
    out.z = z;
    Eigen::Vector2d normal(line.dir.y(), -line.dir.x());
    out.rho = normal.dot(line.mean);
    if (out.rho < 0) normal = -normal, out.rho = -out.rho;
    out.theta = std::atan2(normal.y(), normal.x());
    out.cov = Eigen::Matrix2d::Identity() * 1e-4;  // not used by the spiral search
    out.num_points = count;
    return true;
}

/// [-] straight pieces looked for in one pair's boundary: a tread's nosing and its outer rim (both
/// over the floor for the first wedge of a spiral), rarely more
constexpr int kMaxLinesPerPair = 3;
/// [-] sample points per side for the line hypotheses (32 x 32 / 2 pairs of points)
constexpr int kSamples = 32;
/// [-] times the best hypothesis's inliers are refitted and taken again: the line then hardly
/// depends on which two midpoints made it
constexpr int kRefits = 2;

/// Splits `pts` into those within `tolerance` of the line through `at` with unit `normal` and the
/// rest.
void splitByLine(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& at,
                 const Eigen::Vector2d& normal, double tolerance, std::vector<Eigen::Vector2d>& in,
                 std::vector<Eigen::Vector2d>& out) {
    in.clear();
    out.clear();
    for (const Eigen::Vector2d& q : pts)
        (std::abs(normal.dot(q - at)) <= tolerance ? in : out).push_back(q);
}

/// Straight pieces of one pair's boundary midpoints: the line through two of them that holds the
/// most within max_line_rms_m, refitted to them, then again on the rest.
void fitBoundaries(std::vector<Eigen::Vector2d> left, double z, const TreadBoundaryParams& p,
                   std::vector<LineSegment>& lines) {
    std::vector<Eigen::Vector2d> in, out;
    for (int round = 0; round < kMaxLinesPerPair; ++round) {
        const int m = static_cast<int>(left.size());
        if (m < p.min_line_cells) return;
        const int stride = std::max(1, m / kSamples);
        int best = 0;
        Eigen::Vector2d best_at = Eigen::Vector2d::Zero(), best_normal = Eigen::Vector2d::Zero();
        for (int i = 0; i < m; i += stride)
            for (int j = i + stride; j < m; j += stride) {
                const Eigen::Vector2d d = left[j] - left[i];
                const double len = d.norm();
                if (len < 0.5 * p.min_line_length_m) continue;
                const Eigen::Vector2d normal(-d.y() / len, d.x() / len);
                int count = 0;
                for (const Eigen::Vector2d& q : left)
                    count += std::abs(normal.dot(q - left[i])) <= p.max_line_rms_m;
                if (count > best) best = count, best_at = left[i], best_normal = normal;
            }
        if (best < p.min_line_cells) return;
        splitByLine(left, best_at, best_normal, p.max_line_rms_m, in, out);
        for (int k = 0; k < kRefits && static_cast<int>(in.size()) >= p.min_line_cells; ++k) {
            const PrincipalLine line = principalLine(in);
            splitByLine(left, line.mean, {line.dir.y(), -line.dir.x()}, p.max_line_rms_m, in, out);
        }
        LineSegment l;
        if (boundaryLine(in, z, p, l)) lines.push_back(l);
        if (out.size() == left.size()) return;  // the refits took nothing: nothing more to find
        left.swap(out);
    }
}

}  // namespace

std::vector<LineSegment> treadBoundaryNosings(const HeightGrid& s, const TreadBoundaryParams& p) {
    std::vector<int> label;
    const std::vector<Patch> patches = growPatches(s, p, label);
    std::vector<char> is_flat(patches.size());
    for (std::size_t k = 0; k < patches.size(); ++k)
        is_flat[k] = patches[k].cells >= p.min_patch_cells &&
                     ((k == 0 && p.floor_band_m > 0) ||  // the floor: flat within its band
                      patches[k].spread() <= p.max_patch_spread_m);
    const auto flat = [&](int id) { return id >= 0 && is_flat[id]; };
    // Midpoints between an upper patch's cell and each 4-neighbour of a flat patch a rise below.
    std::vector<BoundaryPoint> pts;
    const int n = s.n;
    const int sides[4] = {1, -1, n, -n};
    for (int c = n; c < static_cast<int>(label.size()) - n; ++c) {
        const int up = label[c];
        if (!flat(up)) continue;
        for (const int d : sides) {
            const int low = label[c + d];  // the border keeps c + d inside the grid
            if (low == up || !flat(low)) continue;
            const double rise = patches[up].mean() - patches[low].mean();
            if (rise < p.min_rise_m || rise > p.max_rise_m) continue;
            pts.push_back({(static_cast<std::uint64_t>(up) << 32) | static_cast<std::uint32_t>(low),
                           0.5 * (s.centre(c) + s.centre(c + d))});
        }
    }
    std::stable_sort(
        pts.begin(), pts.end(),  // each pair's midpoints in cell order
        [](const BoundaryPoint& a, const BoundaryPoint& b) { return a.pair < b.pair; });
    std::vector<LineSegment> lines;
    std::vector<Eigen::Vector2d> boundary;
    for (std::size_t from = 0; from < pts.size();) {
        std::size_t to = from;
        boundary.clear();
        while (to < pts.size() && pts[to].pair == pts[from].pair) boundary.push_back(pts[to++].xy);
        fitBoundaries(boundary, patches[pts[from].pair >> 32].mean(), p, lines);
        from = to;
    }
    return lines;
}

}  // namespace stairmap
