#pragma once
// What a `stairmap map` run reports: stats.json (machine-readable) and the summary on stdout.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "io/rawlog/RawlogScanSource.h"
#include "pipeline/Mapper.h"

namespace stairmap::apps {

/// Wall times of a run [s].
struct MapRunTimes {
    double read_s = 0.0;        ///< reading the rawlog
    double processing_s = 0.0;  ///< the whole replay (reading and mapping)
    double output_s = 0.0;      ///< writing the outputs
};

/// stats.json: the mapper's counters, times, memory, source counters and effective parameters.
nlohmann::json mapStatsJson(const pipeline::Mapper& mapper, const io::RawlogScanSource& source,
                            const pipeline::MapperParams& params, const MapRunTimes& times);

/// The summary on stdout; `signal` (0 if none) or `error` say why a run stopped early.
void printMapSummary(const pipeline::Mapper& mapper, const io::RawlogScanSource& source,
                     const MapRunTimes& times, const std::string& out,
                     const std::optional<std::string>& error, int signal);

}  // namespace stairmap::apps
