// `stairmap merge`: aligns landmark maps made in different frames to the first one and fuses them
// (docs/merge.md). Without --align, each map's 4-DoF transform is estimated from the staircases it
// shares with the maps merged before it; an ambiguous or unsupported alignment is refused.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "Commands.h"
#include "fleet/MapAlignment.h"
#include "fleet/MapFusion.h"
#include "io/json/FleetJson.h"
#include "io/json/LandmarkJson.h"
#include "viz/MapOverview.h"
#include "viz/MapScene.h"

namespace stairmap::apps {
namespace {

namespace fs = std::filesystem;
constexpr double kDegToRad = M_PI / 180.0;

struct MergeOptions {
    std::vector<std::string> maps, aligns;
    std::string out;
    bool quiet = false;
};

/// Names a map answers to in --align: its path as given, its folder's name, its file stem.
bool answersTo(const std::string& path, const std::string& name) {
    const fs::path p(path);
    return name == path || name == p.parent_path().filename().string() ||
           name == p.stem().string();
}

fleet::Transform4 parseTransform(const std::string& text, const std::string& option) {
    std::vector<double> v;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        try {
            std::size_t used = 0;
            v.push_back(std::stod(item, &used));
            if (used != item.size() || !std::isfinite(v.back())) throw std::invalid_argument(item);
        } catch (const std::exception&) {
            throw std::runtime_error("--align " + option + ": '" + item + "' is not a number");
        }
    }
    if (v.size() != 4) throw std::runtime_error("--align " + option + ": expected x,y,z,yaw_deg");
    return {v[0], v[1], v[2], v[3] * kDegToRad};
}

/// --align NAME=x,y,z,yaw_deg -> per map index (0 = first, never aligned).
std::vector<std::optional<fleet::Transform4>> givenTransforms(const MergeOptions& opt) {
    std::vector<std::optional<fleet::Transform4>> given(opt.maps.size());
    for (const std::string& a : opt.aligns) {
        const std::size_t eq = a.find('=');
        if (eq == std::string::npos || eq == 0)
            throw std::runtime_error("--align " + a + ": expected NAME=x,y,z,yaw_deg");
        const std::string name = a.substr(0, eq);
        std::vector<std::size_t> hits;
        for (std::size_t i = 1; i < opt.maps.size(); ++i)
            if (answersTo(opt.maps[i], name)) hits.push_back(i);
        if (hits.size() != 1)
            throw std::runtime_error("--align " + a + ": '" + name + "' names " +
                                     (hits.empty() ? "no map after the first" : "several maps"));
        given[hits.front()] = parseTransform(a.substr(eq + 1), a);
    }
    return given;
}

std::string describe(const fleet::Transform4& T) {
    char text[128];
    std::snprintf(text, sizeof(text), "x %.3f y %.3f z %.3f m, yaw %.2f deg", T.x, T.y, T.z,
                  T.yaw_rad / kDegToRad);
    return text;
}

class MergeRun {
public:
    explicit MergeRun(const MergeOptions& opt) : opt_(opt) {}

    int run() {
        LandmarkParams params;
        LandmarkMapState first = io::loadLandmarkState(opt_.maps.front(), &params);
        fleet::MapFusion fusion(std::move(first), params);
        records_.push_back({opt_.maps.front(), {}, {}, {}});
        const auto given = givenTransforms(opt_);
        for (std::size_t k = 1; k < opt_.maps.size(); ++k) {
            const LandmarkMapState other = io::loadLandmarkState(opt_.maps[k]);
            const fleet::AlignmentResult r = align(fusion.state(), other, given[k], k);
            fusion.add(other, r.T_first_other);
            records_.push_back({opt_.maps[k], r.T_first_other, r.sigma, r.pairs});
        }
        writeOutputs(fusion);
        if (!opt_.quiet) printSummary(fusion);
        return 0;
    }

private:
    fleet::AlignmentResult align(const LandmarkMapState& fused, const LandmarkMapState& other,
                                 const std::optional<fleet::Transform4>& given, std::size_t k) {
        if (given) return fleet::evaluateAlignment(fused, other, *given);
        fleet::AlignmentResult r = fleet::estimateAlignment(fused, other);
        if (r.status != fleet::AlignmentStatus::Aligned) {
            throw std::runtime_error(opt_.maps[k] + ": cannot align to the first map: " + r.reason +
                                     "; give the transform with --align " +
                                     fs::path(opt_.maps[k]).parent_path().filename().string() +
                                     "=x,y,z,yaw_deg");
        }
        return r;
    }

    std::string outPath(const std::string& name) const { return (fs::path(opt_.out) / name).string(); }

    void writeOutputs(const fleet::MapFusion& fusion) const {
        fs::create_directories(opt_.out);
        io::saveLandmarkStateAtomic(outPath("landmarks.json"), fusion.state(), fusion.params());
        viz::MapView view;
        view.staircases = fusion.state().staircases;
        view.floors = LandmarkMap(fusion.state(), fusion.params()).floors();
        viz::saveMapScene(view, outPath("scene.3Dscene"));
        viz::saveMapOverview(view, outPath("overview.png"));
        io::saveAlignment(outPath("alignment.json"), records_);
        io::saveProvenance(outPath("provenance.json"), fusion.provenance(), opt_.maps);
    }

    void printSummary(const fleet::MapFusion& fusion) const {
        std::printf("stairmap merge: done, %zu maps\n", records_.size());
        for (std::size_t k = 1; k < records_.size(); ++k) {
            const io::AlignmentRecord& r = records_[k];
            std::printf("  %s: %s (sigma xy %.3f m, z %.3f m, yaw %.2f deg), %zu shared staircase(s)\n",
                        r.source.c_str(), describe(r.T_first_this).c_str(), r.sigma.xy_m,
                        r.sigma.z_m, r.sigma.yaw_deg, r.pairs.size());
        }
        for (const auto& p : fusion.provenance()) {
            std::printf("  stair #%d: from", p.id);
            for (const auto& c : p.sources) std::printf(" map %d #%d (x%d)", c.map, c.source_id, c.observations);
            std::printf("\n");
        }
        std::printf("  outputs in %s\n", opt_.out.c_str());
    }

    MergeOptions opt_;
    std::vector<io::AlignmentRecord> records_;
};

}  // namespace

Command addMergeCommand(CLI::App& app) {
    auto opt = std::make_shared<MergeOptions>();
    Command command;
    command.cli = app.add_subcommand(
        "merge", "Merge landmark maps made in different frames into the first map's frame.\n"
                 "Each later map's x, y, z, yaw is estimated from the staircases it shares with\n"
                 "the maps before it (or given with --align); refused (exit 2) when the maps do\n"
                 "not share enough to fix it unambiguously. Writes landmarks.json, scene.3Dscene,\n"
                 "overview.png, alignment.json and provenance.json into --out (docs/merge.md).");
    command.cli->add_option("maps", opt->maps, "landmarks.json files; the first fixes the frame")
        ->required()->expected(2, -1)->check(CLI::ExistingFile);
    command.cli->add_option("--out", opt->out, "output directory")->required();
    command.cli->add_option("--align", opt->aligns,
                            "NAME=x,y,z,yaw_deg: map NAME (its path, folder or file stem) is at "
                            "this transform in the first map's frame (m, deg); skips the estimate");
    command.cli->add_flag("--quiet", opt->quiet, "no summary on stdout");
    command.run = [opt]() -> int { return MergeRun(*opt).run(); };
    return command;
}

}  // namespace stairmap::apps
