#include "core/SpiralPieces.h"

#include <cmath>
#include <optional>

#include "core/StaircaseGeometry.h"
#include "core/TurningFlight.h"

namespace stairmap {
namespace {

/// Angle about `axis` of the edge's end farther from it [rad].
double angleAbout(const StairEdge& e, const Eigen::Vector2d& axis) {
    const Eigen::Vector2d a = e.start.head<2>() - axis, b = e.end.head<2>() - axis;
    const Eigen::Vector2d outer = a.squaredNorm() > b.squaredNorm() ? a : b;
    return std::atan2(outer.y(), outer.x());
}

double wrapped(double a) { return std::remainder(a, 2 * M_PI); }

/// Turn direction of a flight about its axis: +1 counter-clockwise going up, -1 clockwise.
double turnSign(const Staircase& s, const Eigen::Vector2d& axis) {
    double sum = 0;
    for (std::size_t i = 1; i < s.steps.size(); ++i)
        sum += wrapped(angleAbout(s.steps[i], axis) - angleAbout(s.steps[i - 1], axis));
    return sum >= 0 ? 1.0 : -1.0;
}

/// The nosing halfway between edges a and b (inner ends paired with inner ends about `axis`).
StairEdge halfwayAbout(const StairEdge& a, const StairEdge& b, const Eigen::Vector2d& axis) {
    const auto innerOuter = [&](const StairEdge& e) {
        const bool start_inner =
            (e.start.head<2>() - axis).squaredNorm() <= (e.end.head<2>() - axis).squaredNorm();
        return start_inner ? std::pair{e.start, e.end} : std::pair{e.end, e.start};
    };
    const auto [ai, ao] = innerOuter(a);
    const auto [bi, bo] = innerOuter(b);
    StairEdge h;
    h.start = 0.5 * (ai + bi);
    h.end = 0.5 * (ao + bo);
    h.cov_rho_theta = Eigen::Matrix2d::Identity() * 1e-2;  // not seen: weighs little
    h.num_points = 0;
    return h;
}

/// Whether two turning flights turn the same way about one axis by one step angle: pieces of one
/// spiral, whatever their heights.
bool onOneSpiral(const Staircase& a, const TurningFlight& ta, const Staircase& b,
                 const TurningFlight& tb, const SpiralPieceParams& p) {
    if ((ta.axis - tb.axis).norm() > p.max_axis_distance_m) return false;
    const double a_lo = std::min(ta.step_angle_rad, tb.step_angle_rad);
    const double a_hi = std::max(ta.step_angle_rad, tb.step_angle_rad);
    if (a_hi > p.max_step_angle_ratio * a_lo) return false;
    const Eigen::Vector2d axis = 0.5 * (ta.axis + tb.axis);
    return turnSign(a, axis) == turnSign(b, axis);
}

/// Whether `upper` continues `lower`'s helix; then the number of levels between (1 or 2).
std::optional<int> continuesHelix(const Staircase& lower, const TurningFlight& tl,
                                  const Staircase& upper, const TurningFlight& tu,
                                  const SpiralPieceParams& p) {
    if (!onOneSpiral(lower, tl, upper, tu, p)) return std::nullopt;
    if (std::abs(lower.step_height - upper.step_height) > p.max_rise_diff_m) return std::nullopt;
    const double a_lo = std::min(tl.step_angle_rad, tu.step_angle_rad);
    const double a_hi = std::max(tl.step_angle_rad, tu.step_angle_rad);
    const Eigen::Vector2d axis = 0.5 * (tl.axis + tu.axis);
    const double sign = turnSign(lower, axis);
    const double rise = 0.5 * (lower.step_height + upper.step_height);
    const double dz = upper.steps.front().start.z() - lower.steps.back().start.z();
    const int k = static_cast<int>(std::lround(dz / rise));
    if (k < 1 || k > 2 || std::abs(dz - k * rise) > p.level_tolerance * rise) return std::nullopt;
    const double step = 0.5 * (a_lo + a_hi);
    const double turn =
        wrapped(angleAbout(upper.steps.front(), axis) - angleAbout(lower.steps.back(), axis));
    if (std::abs(turn - sign * k * step) > p.angle_tolerance * step) return std::nullopt;
    return k;
}

}  // namespace

int joinSpiralPieces(std::vector<Staircase>& flights, const SpiralPieceParams& p) {
    int joined = 0;
    for (bool again = true; again;) {
        again = false;
        for (std::size_t i = 0; i < flights.size() && !again; ++i) {
            for (std::size_t j = 0; j < flights.size() && !again; ++j) {
                Staircase& lower = flights[i];
                const Staircase& upper = flights[j];
                if (i == j || lower.direction != StairDirection::Ascending ||
                    upper.direction != StairDirection::Ascending || lower.steps.empty() ||
                    upper.steps.empty() ||
                    upper.steps.front().start.z() <= lower.steps.back().start.z())
                    continue;
                const auto tl = turningFlight(lower);
                const auto tu = tl ? turningFlight(upper) : std::nullopt;
                if (!tu) continue;
                const auto k = continuesHelix(lower, *tl, upper, *tu, p);
                if (!k) continue;
                const Eigen::Vector2d axis = 0.5 * (tl->axis + tu->axis);
                if (*k == 2)
                    lower.steps.push_back(
                        halfwayAbout(lower.steps.back(), upper.steps.front(), axis));
                lower.steps.insert(lower.steps.end(), upper.steps.begin(), upper.steps.end());
                estimateGeometry(lower);
                flights.erase(flights.begin() + static_cast<std::ptrdiff_t>(j));
                ++joined;
                again = true;
            }
        }
    }
    return joined;
}

int dropSpiralRepeats(std::vector<Staircase>& flights, const SpiralPieceParams& p) {
    std::vector<std::optional<TurningFlight>> turning;
    turning.reserve(flights.size());
    for (const Staircase& s : flights)
        turning.push_back(s.direction == StairDirection::Ascending && !s.steps.empty()
                              ? turningFlight(s)
                              : std::nullopt);
    std::vector<char> drop(flights.size(), 0);
    for (std::size_t i = 0; i < flights.size(); ++i)
        for (std::size_t j = 0; j < flights.size() && !drop[i]; ++j) {
            if (i == j || drop[j] || !turning[i] || !turning[j]) continue;
            const bool j_lower =
                flights[j].steps.front().start.z() < flights[i].steps.front().start.z();
            if (j_lower && onOneSpiral(flights[j], *turning[j], flights[i], *turning[i], p))
                drop[i] = 1;
        }
    std::vector<Staircase> kept;
    for (std::size_t i = 0; i < flights.size(); ++i)
        if (!drop[i]) kept.push_back(std::move(flights[i]));
    const int dropped = static_cast<int>(flights.size() - kept.size());
    flights = std::move(kept);
    return dropped;
}

}  // namespace stairmap
