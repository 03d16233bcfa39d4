#include "io/export/MapServerFiles.h"

#include <filesystem>
#include <sstream>

#include "io/system/AtomicFile.h"

namespace stairmap::io {
namespace {

unsigned char pixel(exporting::Cell c) {
    switch (c) {
        case exporting::Cell::Free:
            return kPgmFree;
        case exporting::Cell::Occupied:
            return kPgmOccupied;
        default:
            return kPgmUnknown;
    }
}

}  // namespace

std::string pgmBytes(const exporting::FloorGrid& grid) {
    std::string out =
        "P5\n" + std::to_string(grid.width) + " " + std::to_string(grid.height) + "\n255\n";
    out.reserve(out.size() + grid.cells.size());
    // map_server puts the image's bottom-left pixel at `origin`: the last row is the lowest y.
    for (int iy = grid.height - 1; iy >= 0; --iy) {
        for (int ix = 0; ix < grid.width; ++ix)
            out.push_back(static_cast<char>(pixel(grid.at(ix, iy))));
    }
    return out;
}

std::string mapYamlText(const std::string& image_file, const exporting::FloorGrid& grid) {
    std::ostringstream y;
    y.precision(10);
    y << "image: " << image_file << "\n"
      << "mode: trinary\n"
      << "resolution: " << grid.resolution_m << "\n"
      << "origin: [" << grid.origin_x << ", " << grid.origin_y << ", 0.0]\n"
      << "negate: 0\n"
      << "occupied_thresh: " << kOccupiedThresh << "\n"
      << "free_thresh: " << kFreeThresh << "\n"
      << "# stairmap: floor surface at z = " << grid.floor_z << " m (world frame)\n";
    return y.str();
}

void saveMapServerMap(const std::string& dir, const std::string& stem,
                      const exporting::FloorGrid& grid) {
    const std::filesystem::path base(dir);
    writeTextFileAtomic((base / (stem + ".pgm")).string(), pgmBytes(grid));
    writeTextFileAtomic((base / (stem + ".yaml")).string(), mapYamlText(stem + ".pgm", grid));
}

}  // namespace stairmap::io
