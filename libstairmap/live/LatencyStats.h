#pragma once
// Median / p95 of a long stream of durations in fixed memory: a uniform reservoir sample
// (Vitter's algorithm R) of at most `capacity` values, plus exact count, mean and max. With the
// default 4096 samples the quantiles of any stream are within ~1-2 percentile points of the
// truth. Not thread-safe (the mapping thread owns it; others read snapshots).

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace stairmap::live {

/// What a LatencyStats reports [s]; zeros when nothing was recorded.
struct LatencySummary {
    std::size_t count = 0;
    double median_s = 0.0;
    double p95_s = 0.0;
    double mean_s = 0.0;
    double max_s = 0.0;
};

class LatencyStats {
public:
    /// capacity: samples kept (>= 1). seed: fixed, so runs are reproducible.
    explicit LatencyStats(std::size_t capacity = 4096, std::uint32_t seed = 1);

    void add(double seconds);
    /// q in [0, 1] (nearest rank over the kept samples). Cost O(capacity).
    double quantile(double q) const;
    LatencySummary summary() const;
    std::size_t count() const { return count_; }
    /// Samples kept now (<= capacity): the memory bound.
    std::size_t kept() const { return samples_.size(); }

private:
    std::size_t capacity_;
    std::vector<double> samples_;
    std::mt19937 rng_;
    std::size_t count_ = 0;
    double sum_ = 0.0;
    double max_ = 0.0;
};

}  // namespace stairmap::live
