#include "live/ScanQueue.h"

#include <stdexcept>

namespace stairmap::live {

ScanQueue::ScanQueue(const ScanQueueParams& params, const std::atomic<bool>& stop)
    : params_(params), stop_(stop) {
    if (params_.capacity == 0) throw std::invalid_argument("ScanQueueParams.capacity must be >= 1");
}

void ScanQueue::push(Scan scan) {
    std::unique_lock<std::mutex> lock(mutex_);
    ++counters_.pushed;
    counters_.newest_stamp_s = scan.stamp_s;
    if (params_.lossy) {
        if (queue_.size() >= params_.capacity) {
            queue_.pop_front();  // the oldest goes: the mapper should see the freshest data
            ++counters_.dropped;
        }
    } else {
        // Re-check the stop flag regularly: it is an atomic the condition variable does not see.
        while (queue_.size() >= params_.capacity && !stop_.load()) {
            not_full_.wait_for(lock, std::chrono::milliseconds(100));
        }
        if (queue_.size() >= params_.capacity) {
            ++counters_.discarded_on_stop;
            return;
        }
    }
    queue_.push_back({std::move(scan), std::chrono::steady_clock::now()});
    counters_.queued = queue_.size();
    if (queue_.size() > counters_.peak_queued) counters_.peak_queued = queue_.size();
    lock.unlock();
    not_empty_.notify_one();
}

std::optional<QueuedScan> ScanQueue::pop(std::chrono::milliseconds wait) {
    std::unique_lock<std::mutex> lock(mutex_);
    not_empty_.wait_for(lock, wait, [this] { return !queue_.empty() || closed_; });
    if (queue_.empty()) return std::nullopt;
    QueuedScan item = std::move(queue_.front());
    queue_.pop_front();
    counters_.queued = queue_.size();
    lock.unlock();
    not_full_.notify_one();
    return item;
}

void ScanQueue::close() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        closed_ = true;
    }
    not_empty_.notify_all();
}

bool ScanQueue::drained() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return closed_ && queue_.empty();
}

void ScanQueue::wake() {
    not_full_.notify_all();
    not_empty_.notify_all();
}

ScanQueueCounters ScanQueue::counters() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return counters_;
}

}  // namespace stairmap::live
