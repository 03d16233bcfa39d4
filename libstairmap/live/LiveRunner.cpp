#include "live/LiveRunner.h"

#include <exception>
#include <thread>

namespace stairmap::live {
namespace {

double secondsBetween(std::chrono::steady_clock::time_point a,
                      std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

}  // namespace

const char* toString(LiveEnd end) {
    switch (end) {
        case LiveEnd::SourceEnded: return "source ended";
        case LiveEnd::StopRequested: return "stop requested";
        case LiveEnd::Duration: return "--duration reached";
        case LiveEnd::MaxScans: return "--max-scans reached";
    }
    return "unknown";
}

LiveRunner::LiveRunner(pipeline::Mapper& mapper, LiveSource& source,
                       const LiveRunnerParams& params)
    : mapper_(mapper),
      source_(source),
      params_(params),
      queue_({params.queue_capacity, source.lossy()}, stop_) {
    mapper_.setLandmarksChangedCallback([this](const LandmarkMap& landmarks) {
        changed_ = true;
        ++landmark_changes_;
        for (LandmarkListener* l : listeners_) l->onLandmarks(landmarks, current_stamp_s_);
    });
}

LiveRunner::~LiveRunner() = default;

void LiveRunner::addListener(LandmarkListener& listener) { listeners_.push_back(&listener); }

void LiveRunner::setTickCallback(std::function<void(const LiveStatus&)> tick) {
    tick_ = std::move(tick);
}

void LiveRunner::setStopCheck(std::function<bool()> check) { stop_check_ = std::move(check); }

// The source runs here; whatever way it ends, the queue is closed so the mapper can finish.
void LiveRunner::sourceThread() {
    try {
        source_.run(queue_, stop_);
    } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(error_mutex_);
        source_error_ = e.what();
    } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex_);
        source_error_ = source_.describe() + ": unexpected error";
    }
    queue_.close();
}

std::optional<LiveEnd> LiveRunner::limitReached() const {
    if (stop_check_ && stop_check_()) return LiveEnd::StopRequested;
    if (params_.max_scans > 0 && mapper_.stats().scans >= params_.max_scans)
        return LiveEnd::MaxScans;
    if (params_.duration_s > 0 && secondsBetween(start_, Clock::now()) >= params_.duration_s)
        return LiveEnd::Duration;
    return std::nullopt;
}

void LiveRunner::mapOne(QueuedScan item) {
    const auto taken = Clock::now();
    current_stamp_s_ = item.scan.stamp_s;
    changed_ = false;
    mapper_.processScan(item.scan);
    const auto done = Clock::now();
    last_stamp_s_ = item.scan.stamp_s;
    queue_wait_.add(secondsBetween(item.arrival, taken));
    processing_.add(secondsBetween(taken, done));
    scan_latency_.add(secondsBetween(item.arrival, done));
    if (changed_) update_latency_.add(secondsBetween(item.arrival, done));
}

void LiveRunner::tickIfDue(bool force) {
    const auto now = Clock::now();
    const double since = secondsBetween(last_tick_, now);
    if (!force && since < params_.tick_period_s) return;
    const std::size_t scans = mapper_.stats().scans;
    if (since > 0) rate_ = (scans - scans_at_last_tick_) / since;
    scans_at_last_tick_ = scans;
    last_tick_ = now;
    if (tick_) tick_(status());
}

LiveEnd LiveRunner::run() {
    start_ = last_tick_ = Clock::now();
    for (LandmarkListener* l : listeners_) l->onLandmarks(mapper_.landmarks(), 0.0);
    std::thread source_thread([this] { sourceThread(); });
    const auto poll = std::chrono::milliseconds(
        static_cast<long>(params_.poll_period_s * 1000.0) > 0
            ? static_cast<long>(params_.poll_period_s * 1000.0) : 1);
    // Whatever ends the loop (also an exception from the mapper, a listener or the tick, e.g. a
    // full disk), the source is stopped and joined before run() leaves.
    const auto stop_source = [&] {
        stop_ = true;  // the source returns within ~0.2 s; a blocked push gives up
        queue_.wake();
        source_thread.join();
    };
    LiveEnd end = LiveEnd::SourceEnded;
    try {
        end = mapUntilEnd(poll);
    } catch (...) {
        stop_source();
        throw;
    }
    stop_source();
    tickIfDue(true);
    return end;
}

LiveEnd LiveRunner::mapUntilEnd(std::chrono::milliseconds poll) {
    for (;;) {
        if (const auto limit = limitReached()) return *limit;
        if (std::optional<QueuedScan> item = queue_.pop(poll)) {
            mapOne(std::move(*item));
        } else if (queue_.drained()) {
            return LiveEnd::SourceEnded;
        }
        tickIfDue(false);
    }
}

LiveStatus LiveRunner::status() const {
    LiveStatus s;
    s.elapsed_s = secondsBetween(start_, Clock::now());
    s.scans_mapped = mapper_.stats().scans;
    s.scans_per_s = rate_;
    s.queue = queue_.counters();
    s.last_stamp_s = last_stamp_s_;
    s.lag_s = s.scans_mapped > 0 && s.queue.newest_stamp_s > last_stamp_s_
                  ? s.queue.newest_stamp_s - last_stamp_s_ : 0.0;
    s.landmark_changes = landmark_changes_;
    s.staircases = mapper_.landmarks().staircases().size();
    s.update_latency = update_latency_.summary();
    s.scan_latency = scan_latency_.summary();
    s.processing = processing_.summary();
    s.queue_wait = queue_wait_.summary();
    s.source_counters = source_.counters();
    s.lossy = source_.lossy();
    return s;
}

}  // namespace stairmap::live
