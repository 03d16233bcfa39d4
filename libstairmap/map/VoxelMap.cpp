#include "map/VoxelMap.h"

#include <octomap/OcTree.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <vector>
#include <fstream>
#include <iostream>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace stairmap::map {
namespace {

void validate(const VoxelMapParams& p) {
    if (!(p.resolution_m > 0.0) || p.resolution_m > 10.0) {
        throw std::invalid_argument("VoxelMapParams.resolution_m must be in (0, 10] m");
    }
    if (!std::isfinite(p.max_range_m)) {
        throw std::invalid_argument("VoxelMapParams.max_range_m must be finite");
    }
}

/// True if p is finite and within max_range of origin (max_range <= 0: no limit).
bool usable(const Eigen::Vector3f& p, const Eigen::Vector3d& origin, double max_range) {
    if (!p.allFinite()) return false;
    if (max_range <= 0.0) return true;
    return (p.cast<double>() - origin).squaredNorm() <= max_range * max_range;
}

/// liboctomap (Debian build) chats on std::cerr and with fprintf(stderr) while reading/writing
/// .bt files; keep our stderr clean by parking both for the duration (single-threaded use).
class QuietCerr {
public:
    QuietCerr() : saved_(std::cerr.rdbuf(sink_.rdbuf())) {
        std::fflush(stderr);
        saved_fd_ = ::dup(STDERR_FILENO);
        const int null_fd = ::open("/dev/null", O_WRONLY);
        if (null_fd >= 0) {
            ::dup2(null_fd, STDERR_FILENO);
            ::close(null_fd);
        }
    }
    ~QuietCerr() {
        std::fflush(stderr);
        if (saved_fd_ >= 0) {
            ::dup2(saved_fd_, STDERR_FILENO);
            ::close(saved_fd_);
        }
        std::cerr.rdbuf(saved_);
    }
    QuietCerr(const QuietCerr&) = delete;
    QuietCerr& operator=(const QuietCerr&) = delete;

private:
    std::ostringstream sink_;
    std::streambuf* saved_;
    int saved_fd_ = -1;
};

std::uint64_t packKey(const octomap::OcTreeKey& k) {
    return static_cast<std::uint64_t>(k[0]) | (static_cast<std::uint64_t>(k[1]) << 16) |
           (static_cast<std::uint64_t>(k[2]) << 32);
}

octomap::OcTreeKey unpackKey(std::uint64_t k) {
    return octomap::OcTreeKey(static_cast<octomap::key_type>(k & 0xFFFF),
                              static_cast<octomap::key_type>((k >> 16) & 0xFFFF),
                              static_cast<octomap::key_type>((k >> 32) & 0xFFFF));
}

}  // namespace

VoxelMap::VoxelMap(const VoxelMapParams& params) : params_(params) {
    validate(params_);
    tree_ = std::make_unique<octomap::OcTree>(params_.resolution_m);
}

VoxelMap::~VoxelMap() = default;
VoxelMap::VoxelMap(VoxelMap&&) noexcept = default;
VoxelMap& VoxelMap::operator=(VoxelMap&&) noexcept = default;

std::size_t VoxelMap::insertScan(const PointCloud& points_world,
                                 const Eigen::Vector3d& origin_world) {
    std::size_t used = 0;
    if (params_.insertion_mode == VoxelInsertionMode::Endpoints) {
        insertEndpoints(points_world, origin_world, used);
    } else {
        insertRays(points_world, origin_world, used);
    }
    return used;
}

void VoxelMap::insertEndpoints(const PointCloud& points_world, const Eigen::Vector3d& origin_world,
                               std::size_t& used) {
    // Discretise first: a voxel hit by 50 points of one scan gets one hit, not 50 (this is both the
    // downsampling and what keeps the occupancy update honest).
    std::vector<std::uint64_t> keys;
    keys.reserve(points_world.size());
    octomap::OcTreeKey key;
    for (const auto& p : points_world) {
        if (!usable(p, origin_world, params_.max_range_m)) continue;
        if (!tree_->coordToKeyChecked(p.x(), p.y(), p.z(), key)) continue;
        keys.push_back(packKey(key));
        ++used;
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    // Lazy: only the leaves are touched here (inner nodes are refreshed once before any query or
    // save). Leaves already clamped at the maximum occupancy cannot change in this mode, so a hash
    // lookup replaces a 16-level tree descent for them (most of a static scene after a few scans).
    const float clamp_max = tree_->getClampingThresMaxLog();
    for (const std::uint64_t k : keys) {
        if (saturated_.count(k) != 0) continue;
        const octomap::OcTreeNode* node = tree_->updateNode(unpackKey(k), true, /*lazy_eval=*/true);
        if (node != nullptr && node->getLogOdds() >= clamp_max) saturated_.insert(k);
    }
    inner_nodes_stale_ = true;
}

void VoxelMap::refreshInnerNodes() const {
    if (!inner_nodes_stale_) return;
    tree_->updateInnerOccupancy();
    inner_nodes_stale_ = false;
}

void VoxelMap::insertRays(const PointCloud& points_world, const Eigen::Vector3d& origin_world,
                          std::size_t& used) {
    octomap::Pointcloud cloud;
    cloud.reserve(points_world.size());
    for (const auto& p : points_world) {
        if (!usable(p, origin_world, params_.max_range_m)) continue;
        cloud.push_back(p.x(), p.y(), p.z());
        ++used;
    }
    const octomap::point3d origin(origin_world.x(), origin_world.y(), origin_world.z());
    tree_->insertPointCloud(cloud, origin, params_.max_range_m > 0 ? params_.max_range_m : -1.0,
                            /*lazy_eval=*/false, /*discretize=*/true);
}

bool VoxelMap::isOccupied(const Eigen::Vector3d& p_world) const {
    refreshInnerNodes();
    const octomap::OcTreeNode* node = tree_->search(p_world.x(), p_world.y(), p_world.z());
    return node != nullptr && tree_->isNodeOccupied(node);
}

PointCloud VoxelMap::occupiedVoxelCentres() const {
    refreshInnerNodes();
    PointCloud centres;
    for (auto it = tree_->begin_leafs(), end = tree_->end_leafs(); it != end; ++it) {
        if (!tree_->isNodeOccupied(*it)) continue;
        const octomap::point3d c = it.getCoordinate();
        centres.emplace_back(c.x(), c.y(), c.z());
    }
    return centres;
}

std::size_t VoxelMap::numLeaves() const { return tree_->getNumLeafNodes(); }

std::size_t VoxelMap::memoryUsageBytes() const { return tree_->memoryUsage(); }

void VoxelMap::writeBinary(std::ostream& out) const {
    refreshInnerNodes();
    const QuietCerr quiet;
    if (!tree_->writeBinaryConst(out) || !out) {
        throw std::runtime_error("VoxelMap: writing the OctoMap binary stream failed");
    }
}

void VoxelMap::save(const std::string& path) const {
    refreshInnerNodes();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    const QuietCerr quiet;
    if (!tree_->writeBinaryConst(out) || !out.flush()) {
        throw std::runtime_error(path + ": writing the OctoMap binary file failed");
    }
}

VoxelMap VoxelMap::readBinary(std::istream& in, const std::string& source_name) {
    // Peek at the header for the resolution; octomap's readBinary keeps the tree's resolution
    // otherwise. Read everything into memory so we can parse twice.
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string data = buffer.str();
    std::istringstream header(data);
    std::string line;
    double res = 0.0;
    while (std::getline(header, line)) {
        if (line.rfind("res ", 0) == 0) res = std::strtod(line.c_str() + 4, nullptr);
        if (line == "data") break;
    }
    if (!(res > 0.0)) throw std::runtime_error(source_name + ": not an OctoMap .bt file (no res)");
    VoxelMapParams params;
    params.resolution_m = res;
    VoxelMap map(params);
    std::istringstream body(data);
    const QuietCerr quiet;
    if (!map.tree_->readBinary(body)) {
        throw std::runtime_error(source_name + ": not a valid OctoMap binary (.bt) file");
    }
    return map;
}

VoxelMap VoxelMap::load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open for reading");
    return readBinary(in, path);
}

}  // namespace stairmap::map
