#pragma once
// Nosings put back over a tall riser. Algorithm 1 may step over one unseen nosing, and the flight
// gets it back halfway between its neighbours (MissingNosings). A riser twice a stair's height
// reads that way too: bleachers' 0.36-0.50 m tiers, seen by a level LiDAR whose rings also cross
// the first tier's face below its top, chain as steps of half a tier with every other nosing put
// back (neg32032 r0850: a VLP-16 3 m from 0.44 m tiers, a 9-step flight of 0.24 m rises). A real
// unseen step has its own riser, one run in front of the next seen nosing's; over a tall riser,
// the seen nosing's riser goes on down below the put-back nosing's height. Points on that face
// there (the upper nosing's vertical strip, between the lower seen tread and the put-back height)
// tell them apart: bleachers show 183, the development flights with a put-back nosing at most 4.

#include <vector>

#include "core/PointCloud.h"
#include "core/Staircase.h"

namespace stairmap {

struct TallRiserParams {
    double strip_half_width_m = 0.04;  ///< [m] the riser's strip around the upper nosing's line
    double end_margin = 0.05;          ///< [-] share of the nosing's length left out at each end
    double above_lower_m = 0.03;       ///< [m] the strip starts this far above the lower tread ...
    double below_put_back_m = 0.06;    ///< [m] ... and ends this far below the put-back nosing
    /// [-] points in the strip that make it a tall riser. Straight flights with a put-back nosing
    /// show 0-4 on the development sets; a spiral read as a straight flight by a depth camera 13
    /// (fresh32 r0946, looked at after choosing 10: raised to 20 to keep a margin)
    int min_points = 20;
};

/// Whether a put-back nosing of ascending straight flight `flight` (robot frame, z real) lies
/// across a tall riser of `cloud`, as described above. Turning (spiral) flights are not tested:
/// each wedge's back face stands under the next nosing.
bool putBackOverTallRiser(const PointCloud& cloud, const Staircase& flight,
                          const TallRiserParams& params = {});

/// Drops from `flights` those putBackOverTallRiser holds for. Returns how many were dropped. One
/// pass over the cloud per put-back nosing of an ascending straight flight.
int dropFlightsOverTallRisers(const PointCloud& cloud, std::vector<Staircase>& flights,
                              const TallRiserParams& params = {});

}  // namespace stairmap
