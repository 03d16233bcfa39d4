#pragma once
// The voxel map of everything seen: an octomap::OcTree behind one small adapter (world frame).
//
// Insertion modes and their measured cost on this machine (30k-point scan, 5 cm; see bench_mapper
// and ../shared/notes/MRPT-2.5.md §2):
//   - Endpoints: only the voxels hit by the (range-limited) points are marked occupied, each voxel
//     once per scan (the scan is discretised to unique voxel keys first). A few ms per scan.
//     No free space is carved: moving objects leave traces. This is the default.
//   - RayCast: octomap's insertPointCloud (discretised) also marks free space along every ray.
//     1-2 s per 30k-point scan at 5 cm: only for offline maps or tiny scans.

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <unordered_set>

#include "core/PointCloud.h"
#include "map/VoxelMapParams.h"

namespace octomap {
class OcTree;
}

namespace stairmap::map {

class VoxelMap {
public:
    /// Throws std::invalid_argument naming the field if a parameter is out of range.
    explicit VoxelMap(const VoxelMapParams& params = {});
    ~VoxelMap();
    VoxelMap(VoxelMap&&) noexcept;
    VoxelMap& operator=(VoxelMap&&) noexcept;

    /// Inserts one scan given in the world frame, seen from origin_world (the sensor or robot
    /// position). Non-finite points are ignored. Returns the number of points used.
    std::size_t insertScan(const PointCloud& points_world, const Eigen::Vector3d& origin_world);

    /// True if the leaf voxel containing p_world is known and occupied.
    bool isOccupied(const Eigen::Vector3d& p_world) const;
    /// Centres of all occupied leaves (world frame), e.g. for visualisation. Cost: O(leaves).
    PointCloud occupiedVoxelCentres() const;

    std::size_t numLeaves() const;
    std::size_t memoryUsageBytes() const;  ///< octomap's own estimate (malloc overhead excluded)
    double resolution() const { return params_.resolution_m; }
    const VoxelMapParams& params() const { return params_; }

    /// OctoMap binary format (.bt, opens in octovis). Throws std::runtime_error on stream failure.
    void writeBinary(std::ostream& out) const;
    /// Writes `path` (a .bt file). Throws std::runtime_error naming the path on failure.
    void save(const std::string& path) const;
    /// Reads a .bt stream / file (resolution taken from the file). Throws std::runtime_error
    /// naming the source if it is not a valid OctoMap binary file.
    static VoxelMap readBinary(std::istream& in, const std::string& source_name = "stream");
    static VoxelMap load(const std::string& path);

private:
    VoxelMapParams params_;
    std::unique_ptr<octomap::OcTree> tree_;
    std::unordered_set<std::uint64_t> saturated_;  ///< packed keys of leaves clamped occupied
    mutable bool inner_nodes_stale_ = false;  ///< lazy leaf updates not yet propagated upwards

    void refreshInnerNodes() const;

    void insertEndpoints(const PointCloud& points_world, const Eigen::Vector3d& origin_world,
                         std::size_t& used);
    void insertRays(const PointCloud& points_world, const Eigen::Vector3d& origin_world,
                    std::size_t& used);
};

}  // namespace stairmap::map
