#pragma once
// `stairmap annotate`: a copy of a rawlog with stairmap's results on its timeline. The log is
// mapped as `stairmap map` does; after the 3D scan of each detector run a CObservation3DScene
// (sensor label "stairmap", the scan's timestamp) is inserted holding that run's detections and
// the landmarks so far, so MRPT's RawLogViewer shows them. Every other object is copied as read.

#include <cstddef>
#include <string>

namespace stairmap::io {

struct AnnotateOptions {
    std::string in, out;  ///< rawlogs (the output is gzipped when the input is)
    std::string poses;    ///< TUM trajectory, "" = poses from the rawlog
    std::string config;   ///< INI file, "" = built-in defaults
    std::string label = "stairmap";  ///< sensor label of the inserted scenes
};

struct AnnotateStats {
    std::size_t objects_copied = 0;  ///< objects of the input, written unchanged
    std::size_t scenes_inserted = 0; ///< CObservation3DScene added (one per detector run)
    std::size_t detector_runs = 0;
    std::size_t detections = 0;
};

/// Throws std::runtime_error naming the file on bad input (missing, corrupt, same in and out).
AnnotateStats annotateRawlog(const AnnotateOptions& options);

}  // namespace stairmap::io
