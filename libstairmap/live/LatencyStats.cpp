#include "live/LatencyStats.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stairmap::live {

LatencyStats::LatencyStats(std::size_t capacity, std::uint32_t seed)
    : capacity_(capacity), rng_(seed) {
    if (capacity_ == 0) throw std::invalid_argument("LatencyStats capacity must be >= 1");
    samples_.reserve(capacity_);
}

void LatencyStats::add(double seconds) {
    ++count_;
    sum_ += seconds;
    max_ = std::max(max_, seconds);
    if (samples_.size() < capacity_) {
        samples_.push_back(seconds);
        return;
    }
    // Algorithm R: the n-th value replaces a random kept one with probability capacity / n,
    // so every value seen so far is kept with the same probability.
    std::uniform_int_distribution<std::size_t> pick(0, count_ - 1);
    const std::size_t slot = pick(rng_);
    if (slot < capacity_) samples_[slot] = seconds;
}

double LatencyStats::quantile(double q) const {
    if (samples_.empty()) return 0.0;
    std::vector<double> sorted = samples_;
    const double clamped = std::clamp(q, 0.0, 1.0);
    const auto rank = static_cast<std::size_t>(std::ceil(clamped * sorted.size()));
    const std::size_t k = rank == 0 ? 0 : rank - 1;
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
    return sorted[k];
}

LatencySummary LatencyStats::summary() const {
    LatencySummary s;
    s.count = count_;
    if (count_ == 0) return s;
    s.median_s = quantile(0.5);
    s.p95_s = quantile(0.95);
    s.mean_s = sum_ / count_;
    s.max_s = max_;
    return s;
}

}  // namespace stairmap::live
