// `stairmap sim` and `stairmap eval` end to end through the CLI.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "CliRunner.h"
#include "io/cloud/CloudFile.h"
#include "io/json/GroundTruthJson.h"
#include "io/json/StaircaseJson.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;

const char* kTinyScene =
    "[scene]\nname = tiny\ntype = ascending\nseed = 3\n"
    "[stair]\nnum_risers = 4\nrise_m = 0.18\nrun_m = 0.3\nwidth_m = 1.0\n"
    "[sensor]\nmodel = vlp16\nhorizontal_resolution_deg = 2.0\nmax_range_m = 10\n"
    "[trajectory]\nwaypoints = -4 0 0; -1 0 0\nspeed_mps = 1.0\nscan_rate_hz = 1.0\n"
    "[clouds]\nposes = -2 0 0 0\nscans_per_cloud = 1\n";

TEST(SimEvalCli, SimWritesRawlogTrajectoriesCloudAndTruth) {
    const auto dir = cliScratchDir("sim_cli", "tiny");
    std::ofstream(dir + "/tiny.ini") << kTinyScene;
    const auto r = runStairmap("sim '" + dir + "/tiny.ini' --out '" + dir + "/out' -q", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f : {"tiny.rawlog", "poses.tum", "gt_trajectory.tum", "gt.json", "tiny_0.pcd",
                          "tiny_0.gt.json"}) {
        EXPECT_TRUE(fs::exists(dir + "/out/" + f)) << f;
    }
    const auto cloud = io::readCloudFile(dir + "/out/tiny_0.pcd");
    EXPECT_GT(cloud.size(), 500u);
    const auto truth = io::readGroundTruthFile(dir + "/out/tiny_0.gt.json");
    ASSERT_EQ(truth.staircases.size(), 1u);
    EXPECT_EQ(truth.frame, "robot");
    // Robot 2 m before the foot, facing it: first nosing 2 m ahead at rise - base height.
    EXPECT_NEAR(truth.staircases[0].nosings[0].centre().x(), 2.0, 1e-9);
    EXPECT_NEAR(truth.staircases[0].nosings[0].centre().z(), 0.18 - 0.35, 1e-9);
    // 3 m at 1 m/s and 1 Hz: 4 scans, one pose line each.
    std::ifstream poses(dir + "/out/poses.tum");
    int lines = 0;
    for (std::string line; std::getline(poses, line);) lines += !line.empty() && line[0] != '#';
    EXPECT_EQ(lines, 4);
}

TEST(SimEvalCli, SimBadSceneExitsTwoNamingFileAndKey) {
    const auto dir = cliScratchDir("sim_cli", "bad");
    std::ofstream(dir + "/bad.ini") << "[scene]\ntype = ascending\n[stair]\nwidth_m = wide\n[clouds]\nposes = 0 0 0 0\n";
    const auto r = runStairmap("sim '" + dir + "/bad.ini' --out '" + dir + "/out'", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.ini"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("width_m"), std::string::npos) << r.err;
}

TEST(SimEvalCli, EvalScoresADetectOutputAgainstItsTruth) {
    const auto dir = cliScratchDir("eval_cli", "one");
    SceneTruth truth;
    truth.frame = "robot";
    truth.observer_floor_z = -0.4;
    StaircaseTruth s;
    s.name = "flight";
    s.rise_m = 0.2;
    s.run_m = 0.3;
    s.width_m = 1.0;
    s.num_risers = 3;
    s.seen_as = StairDirection::Ascending;
    Staircase d;
    for (int i = 1; i <= 3; ++i) {
        const double x = 2.0 + 0.3 * (i - 1), z = -0.4 + 0.2 * i;
        s.nosings.push_back({{x, -0.5, z}, {x, 0.5, z}});
        StairEdge e;
        e.start = {x, -0.4, z};
        e.end = {x, 0.4, z};
        d.steps.push_back(e);
    }
    truth.staircases = {s};
    io::writeGroundTruthFile(dir + "/cloud_7.gt.json", truth, {{"kind", "ascending"}});
    d.step_height = 0.22;  // 2 cm
    d.step_depth = 0.31;   // 1 cm
    d.step_width = 0.8;    // 20 cm
    d.location = d.steps.front().centre();
    const nlohmann::json det = {{"staircases", {io::toJson(d)}}, {"time_ms", 12.5}};
    std::ofstream(dir + "/cloud_7.json") << det.dump();
    const auto r = runStairmap("eval '" + dir + "/cloud_7.json' --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& total = j.at("total");
    EXPECT_EQ(total.at("samples").get<int>(), 1);
    EXPECT_EQ(total.at("detections").get<int>(), 1);
    EXPECT_EQ(total.at("false_positives").get<int>(), 0);
    EXPECT_NEAR(total.at("mae_height_cm").get<double>(), 2.0, 1e-6);
    EXPECT_NEAR(total.at("mae_depth_cm").get<double>(), 1.0, 1e-6);
    EXPECT_NEAR(total.at("mae_width_cm").get<double>(), 20.0, 1e-6);
    EXPECT_NEAR(total.at("mae_location_cm").get<double>(), 0.0, 1e-6);
    EXPECT_NEAR(total.at("mean_time_ms").get<double>(), 12.5, 1e-9);
    EXPECT_EQ(total.at("false_positives_on_flights").get<int>(), 0);
    // The flight read twice more, once 10 cm too high: two false positives, both on it; the text
    // report says so after its table and on the sample's line.
    Staircase high = d;
    for (StairEdge& e : high.steps) {
        e.start.z() += 0.10;
        e.end.z() += 0.10;
    }
    high.location = high.steps.front().centre();
    const nlohmann::json thrice = {
        {"staircases", {io::toJson(d), io::toJson(d), io::toJson(high)}}};
    io::writeGroundTruthFile(dir + "/cloud_8.gt.json", truth, {{"kind", "ascending"}});
    std::ofstream(dir + "/cloud_8.json") << thrice.dump();
    const auto twice = runStairmap("eval '" + dir + "/cloud_8.json' --json", dir);
    ASSERT_EQ(twice.exit_code, 0) << twice.err;
    const auto t8 = nlohmann::json::parse(twice.out).at("total");
    EXPECT_EQ(t8.at("false_positives").get<int>(), 2);
    EXPECT_EQ(t8.at("false_positives_on_flights").get<int>(), 2);
    const auto text = runStairmap("eval '" + dir + "/cloud_8.json'", dir);
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("false positives on true flights (heights misread, or a flight read "
                            "twice): 2 of 2"),
              std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("cloud_8.json 2 (2 on a true flight)"), std::string::npos) << text.out;
    // Without a truth file the command fails cleanly.
    std::ofstream(dir + "/orphan.json") << det.dump();
    const auto bad = runStairmap("eval '" + dir + "/orphan.json'", dir);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("orphan"), std::string::npos) << bad.err;
}


// --perturb-m: the bundled clouds detected again in perturbed realisations (every coordinate moved
// by up to 0.01 mm). The truth is the bundled one: every flight is still found, none added; the
// realisation is reported, is the same for the same seed, and differs from the unperturbed run.
TEST(SimEvalCli, EvalDetectsPerturbedRealisationsOfTheBundledClouds) {
    const auto dir = cliScratchDir("eval_cli", "perturbed");
    const std::string clouds = std::string("'") + STAIRMAP_SOURCE_DIR + "/datasets/clouds'";
    auto run = [&](const std::string& extra) {
        const auto r = runStairmap("eval --detect " + clouds + " --json " + extra, dir);
        EXPECT_EQ(r.exit_code, 0) << extra << ": " << r.err;
        return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
    };
    // Per-sample errors (rise, run, width...), which a realisation moves by a fraction of a mm.
    auto errors = [](const nlohmann::json& j) {
        std::vector<nlohmann::json> e;
        for (const auto& s : j.at("samples")) e.push_back(s.at("errors"));
        return e;
    };
    const auto plain = run("");
    ASSERT_FALSE(plain.contains("perturbation"));
    for (const int seed : {1, 2}) {
        const auto j = run("--perturb-m 1e-5 --perturb-seed " + std::to_string(seed));
        ASSERT_TRUE(j.contains("perturbation")) << seed;
        EXPECT_DOUBLE_EQ(j.at("perturbation").at("amplitude_m").get<double>(), 1e-5);
        EXPECT_EQ(j.at("perturbation").at("seed").get<int>(), seed);
        const auto& total = j.at("total");
        EXPECT_EQ(total.at("samples").get<int>(), 30) << seed;
        EXPECT_EQ(total.at("detections").get<int>(), 30) << seed;
        EXPECT_EQ(total.at("false_positives").get<int>(), 0) << seed;
        EXPECT_NE(errors(j), errors(plain)) << "seed " << seed << " changed nothing";
        if (seed == 1) {
            const auto again = run("--perturb-m 1e-5 --perturb-seed 1");
            EXPECT_EQ(errors(again), errors(j)) << "the same seed, another realisation";
        }
    }
    const auto text = runStairmap("eval --detect " + clouds + " --perturb-m 1e-5", dir);
    EXPECT_NE(text.out.find("perturbed realisation: every coordinate moved by up to 1e-05 m (seed 1)"),
              std::string::npos)
        << text.out;
    for (const char* bad : {"0.02", "-1e-5", "nan", "wide"}) {
        const auto r = runStairmap("eval --detect " + clouds + " --perturb-m " + bad, dir);
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find("perturb"), std::string::npos) << bad << ": " << r.err;
    }
    // Without --detect there is no cloud to perturb: refused, not ignored.
    const auto scored = runStairmap("eval " + clouds + " --perturb-m 1e-5", dir);
    EXPECT_EQ(scored.exit_code, 2);
    EXPECT_NE(scored.err.find("--detect"), std::string::npos) << scored.err;
}

}  // namespace
}  // namespace stairmap::test
