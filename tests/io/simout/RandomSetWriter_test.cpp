// `stairmap sim --random`'s writer: every scene gets a cloud and a gt.json the evaluation reads,
// labelled with the drawn family, and a rerun with the same seed writes the same files.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/cloud/CloudFile.h"
#include "io/eval/EvalInputs.h"
#include "io/json/GroundTruthJson.h"
#include "io/simout/RandomSetWriter.h"
#include "sim/RandomScene.h"

namespace fs = std::filesystem;

namespace stairmap::io {
namespace {

TEST(RandomSetWriter, WritesCloudsWithTruthTheEvaluationReads) {
    const fs::path dir = fs::path(STAIRMAP_TEST_TMP) / "random_set";
    fs::remove_all(dir);
    RandomSetOptions options;
    options.seed = 21;
    options.count = 3;
    options.jobs = 2;
    const auto summary = writeRandomSet(dir.string(), options);
    EXPECT_EQ(summary.clouds, 3);
    const auto clouds = findCloudsWithTruth({dir.string()});
    ASSERT_EQ(clouds.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        const auto spec = sim::drawRandomScene(21, i);
        const std::string stem = "r000" + std::to_string(i) + "_" + sim::familyName(spec.family);
        const fs::path gt = dir / (stem + ".gt.json");
        ASSERT_TRUE(fs::exists(gt)) << gt;
        EXPECT_EQ(sampleKind(gt.string()), sim::familyName(spec.family));
        const SceneTruth truth = readGroundTruthFile(gt.string());
        EXPECT_EQ(truth.frame, "robot");
        EXPECT_EQ(truth.staircases.size(), spec.flights.size());
        std::ifstream in(gt);
        const auto j = nlohmann::json::parse(in);
        EXPECT_EQ(j["sensor"].get<std::string>(), j["scene_spec"]["sensor"]["model"].get<std::string>());
        EXPECT_EQ(readCloudFile((dir / (stem + ".pcd.gz")).string()).size(), j["points"].get<std::size_t>());
    }
}

}  // namespace
}  // namespace stairmap::io
