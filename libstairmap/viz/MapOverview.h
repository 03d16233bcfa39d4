#pragma once
// A headless overview picture of the map (overview.png): one top view per floor and a side view,
// staircases drawn as their step edges and labelled with their IDs. Drawn directly into an
// mrpt::img::CImage (no OpenGL context needed).

#include <string>

#include "viz/MapScene.h"

namespace stairmap::viz {

struct OverviewParams {
    int panel_px = 480;             ///< [px] side of each square panel
    double floor_band_below_m = 0.3;  ///< [m] a floor's top view starts this far below its z ...
    double floor_band_above_m = 2.0;  ///< [m] ... and ends this far above it (ceilings excluded)
};

/// Renders the overview and writes it as PNG to `path`. Throws std::runtime_error naming the path.
void saveMapOverview(const MapView& view, const std::string& path, const OverviewParams& params = {});

}  // namespace stairmap::viz
