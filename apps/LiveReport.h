#pragma once
// What a `stairmap live` run reports: stats.json (rewritten every few seconds and at the end), the
// status line on stderr and the summary on stdout.

#include <nlohmann/json.hpp>
#include <string>

#include "live/LiveRunner.h"
#include "pipeline/Mapper.h"

namespace stairmap::apps {

/// stats.json: the live figures (rate, lag, drops, latency median/p95 [ms], queue, source
/// counters), the mapper's counters, memory and the effective parameters. `ended`: why the run
/// ended, or "running" for the periodic rewrites.
nlohmann::json liveStatsJson(const pipeline::Mapper& mapper, const live::LiveStatus& status,
                             const std::string& source, std::size_t queue_capacity,
                             const std::string& ended);

/// The one-line status: scans/s, lag, dropped scans, landmarks.
std::string liveStatusLine(const live::LiveStatus& status);

/// The summary on stdout at the end.
void printLiveSummary(const pipeline::Mapper& mapper, const live::LiveStatus& status,
                      const std::string& source, const std::string& ended, const std::string& out);

}  // namespace stairmap::apps
