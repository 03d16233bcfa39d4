// `stairmap view --headless` and `stairmap annotate` end to end on the bundled two-floor log:
// frames counted and not blank, the landmark colour appears once a staircase is confirmed,
// videos through ffmpeg (and one clear line without it), map folders, annotate read back with
// MRPT's CRawlog and rawlog-edit, bad input -> one line, exit 2.
#include <gtest/gtest.h>

#include <mrpt/img/CImage.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservation3DScene.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "CliRunner.h"
#include "ImageChecks.h"
#include "viz/ViewerScene.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;
const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/";
const std::string kLog = "'" + kData + "two_floor.rawlog' --poses '" + kData +
                         "poses.tum' --config '" + STAIRMAP_SOURCE_DIR + "/config/sim_legged_vlp16.ini'";

std::vector<fs::path> pngs(const std::string& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".png") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

mrpt::img::CImage load(const fs::path& p) {
    mrpt::img::CImage img;
    EXPECT_TRUE(img.loadFromFile(p.string())) << p;
    return img;
}

/// Pixels of the background colour (dark grey 31,31,36).
double backgroundFraction(const mrpt::img::CImage& img) {
    const unsigned char bg[3] = {31, 31, 36};
    return double(pixelsNear(img, bg, 6)) / (img.getWidth() * img.getHeight());
}

TEST(ViewCli, HeadlessFramesShowTheReplay) {
    const std::string dir = cliScratchDir("view", "frames");
    const CliResult r = runStairmap("view " + kLog + " --headless --frames '" + dir +
                                        "/f' --every 20 --size 640x360 --camera top",
                                    dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = pngs(dir + "/f");
    ASSERT_EQ(files.size(), 5u);  // scans 20, 40, 60, 80 and the last (83)
    const auto first = load(files.front()), last = load(files.back());
    EXPECT_EQ(first.getWidth(), 640u);
    EXPECT_EQ(first.getHeight(), 360u);
    EXPECT_LT(backgroundFraction(first), 0.9) << "first frame is blank";
    EXPECT_LT(backgroundFraction(last), 0.9) << "last frame is blank";
    EXPECT_GT(differingFraction(first, last), 0.05) << "the map did not grow between frames";
    // Both flights are confirmed by the end of the log (README), none after 20 scans.
    EXPECT_EQ(pixelsNear(first, viz::kConfirmedRgb), 0u);
    EXPECT_GT(pixelsNear(last, viz::kConfirmedRgb), 30u);
}

TEST(ViewCli, VideoNeedsFfmpegAndSaysSo) {
    const std::string dir = cliScratchDir("view", "video");
    const std::string command = std::string("env PATH=/nonexistent '") + STAIRMAP_BIN + "' view " +
                                kLog + " --headless --video '" + dir + "/v.mp4' >'" + dir +
                                "/o.txt' 2>'" + dir + "/e.txt'";
    const int status = std::system(command.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 2);
    const std::string err = readText(dir + "/e.txt");
    EXPECT_NE(err.find("ffmpeg"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    const CliResult ok = runStairmap("view " + kLog + " --headless --video '" + dir +
                                         "/v.mp4' --every 10 --size 320x180", dir);
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    const std::string mp4 = readText(dir + "/v.mp4");
    ASSERT_GT(mp4.size(), 1000u);
    EXPECT_EQ(mp4.substr(4, 4), "ftyp");  // an MP4 container
}

TEST(ViewCli, BrowsesAFinishedMapFolder) {
    const std::string dir = cliScratchDir("view", "folder");
    ASSERT_EQ(runStairmap("map " + kLog + " --quiet --out '" + dir + "/map'", dir).exit_code, 0);
    const CliResult r = runStairmap("view '" + dir + "/map' --headless --frames '" + dir +
                                        "/f' --camera top --size 480x270", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = pngs(dir + "/f");
    ASSERT_EQ(files.size(), 1u);
    EXPECT_GT(pixelsNear(load(files[0]), viz::kConfirmedRgb), 50u);
}

TEST(ViewCli, BadInputIsOneLineAndExit2) {
    const std::string dir = cliScratchDir("view", "bad");
    fs::create_directories(dir + "/empty");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"view /nonexistent.rawlog --headless --frames x", "nonexistent"},
        {"view '" + dir + "/empty' --headless --frames x", "landmarks.json"},
        {"view " + kLog + " --headless --frames x --size 12x", "--size"},
        {"view " + kLog + " --headless --frames x --camera side", "--camera"},
        {"view " + kLog + " --headless", "--frames"},
        {"view " + kLog + " --headless --frames x --hide ceiling", "ceiling"},
        {"annotate /nonexistent.rawlog out.rawlog", "nonexistent"},
        {"annotate '" + kData + "two_floor.rawlog' '" + kData + "two_floor.rawlog'", "output"},
    };
    for (const auto& [args, needle] : cases) {
        const CliResult r = runStairmap(args, dir);
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
        EXPECT_NE(r.err.find(needle), std::string::npos) << args << ": " << r.err;
    }
    const std::string no_display = std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") +
                                   STAIRMAP_BIN + "' view " + kLog + " 2>'" + dir + "/e.txt'";
    EXPECT_EQ(WEXITSTATUS(std::system(no_display.c_str())), 2);
    EXPECT_NE(readText(dir + "/e.txt").find("no display"), std::string::npos);
}

/// Serialized bytes of one object (to compare objects for identity).
std::string bytesOf(const mrpt::serialization::CSerializable& object) {
    mrpt::io::CMemoryStream mem;
    auto arch = mrpt::serialization::archiveFrom(mem);
    arch.WriteObject(&object);
    return std::string(static_cast<const char*>(mem.getRawBufferData()), mem.getTotalBytesCount());
}

TEST(AnnotateCli, InsertsOneSceneePerDetectorRunAndKeepsEverythingElse) {
    const std::string dir = cliScratchDir("annotate", "two_floor");
    ASSERT_EQ(runStairmap("map " + kLog + " --quiet --out '" + dir + "/map'", dir).exit_code, 0);
    const auto stats = nlohmann::json::parse(readText(dir + "/map/stats.json"));
    const std::size_t runs = stats.at("detector_runs").get<std::size_t>();
    ASSERT_GT(runs, 10u);
    const std::string out = dir + "/annotated.rawlog";
    const CliResult r = runStairmap(
        "annotate '" + kData + "two_floor.rawlog' '" + out + "' --poses '" + kData +
            "poses.tum' --config '" + STAIRMAP_SOURCE_DIR + "/config/sim_legged_vlp16.ini'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;

    mrpt::obs::CRawlog in, annotated;
    ASSERT_TRUE(in.loadFromRawLogFile(kData + "two_floor.rawlog"));
    ASSERT_TRUE(annotated.loadFromRawLogFile(out));
    ASSERT_EQ(annotated.size(), in.size() + runs);
    std::size_t scenes = 0, k = 0;
    for (std::size_t i = 0; i < annotated.size(); ++i) {
        const auto obj = annotated.getAsGeneric(i);
        if (const auto* s = dynamic_cast<const mrpt::obs::CObservation3DScene*>(obj.get())) {
            ++scenes;
            ASSERT_TRUE(s->scene);
            EXPECT_TRUE(s->scene->getByName("stairmap/landmarks")) << "scene " << scenes;
            ASSERT_GT(k, 0u) << "a scene before any scan";
            continue;
        }
        ASSERT_LT(k, in.size());
        EXPECT_EQ(bytesOf(*obj), bytesOf(*in.getAsGeneric(k))) << "object " << k << " changed";
        ++k;
    }
    EXPECT_EQ(scenes, runs);
    EXPECT_EQ(k, in.size());
    // MRPT's own tool reads it too and counts every object.
    const CliResult info = [&] {
        CliResult res;
        const std::string cmd = "rawlog-edit --info -i '" + out + "' >'" + dir + "/info.txt' 2>&1";
        res.exit_code = WEXITSTATUS(std::system(cmd.c_str()));
        res.out = readText(dir + "/info.txt");
        return res;
    }();
    ASSERT_EQ(info.exit_code, 0) << info.out;
    EXPECT_NE(info.out.find("Overall number of objects         : " +
                            std::to_string(in.size() + runs)),
              std::string::npos) << info.out;
}

}  // namespace
}  // namespace stairmap::test
