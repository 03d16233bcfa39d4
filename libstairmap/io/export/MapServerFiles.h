#pragma once
// Floor maps in the ROS map_server format (also read by mrpt_map_server and by MRPT's
// COccupancyGridMap2D from the PGM): an 8-bit binary PGM (P5) whose first row is the grid's
// highest y, and a YAML file with image, mode, resolution, origin, negate, occupied_thresh and
// free_thresh. Cells are written as map_saver writes trinary maps: free 254, occupied 0,
// unknown 205.

#include <iosfwd>
#include <string>

#include "export/FloorGrid.h"

namespace stairmap::io {

constexpr unsigned char kPgmFree = 254, kPgmOccupied = 0, kPgmUnknown = 205;
// map_saver's thresholds: unknown (205) reads as p = 50 / 255 = 0.196078, just above free_thresh.
constexpr double kOccupiedThresh = 0.65, kFreeThresh = 0.196;

/// The PGM bytes of a grid (header "P5\n<w> <h>\n255\n", rows from the highest y down).
std::string pgmBytes(const exporting::FloorGrid& grid);
/// The YAML text naming `image_file` (relative to the YAML file, as map_server resolves it).
std::string mapYamlText(const std::string& image_file, const exporting::FloorGrid& grid);

/// Writes `<dir>/<stem>.pgm` and `<dir>/<stem>.yaml` atomically. Throws std::runtime_error
/// naming the file on failure.
void saveMapServerMap(const std::string& dir, const std::string& stem,
                      const exporting::FloorGrid& grid);

}  // namespace stairmap::io
