// `stairmap eval`: scores staircase detections against simulated ground truth (paper Tables I/II).
//   stairmap eval --detect datasets/clouds          run the detector on every cloud with a .gt.json
//   stairmap eval DET.json... [--gt gt.json]...      score `stairmap detect` outputs / landmarks.json maps
// Matching rule and table columns: core/Evaluation.h and docs/simulator.md.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "Commands.h"
#include "core/CloudPerturbation.h"
#include "core/Evaluation.h"
#include "core/StairDetector.h"
#include "io/cloud/CloudFile.h"
#include "io/config/DetectorConfig.h"
#include "io/eval/EvalInputs.h"
#include "io/eval/EvalJson.h"
#include "io/json/GroundTruthJson.h"
#include "io/config/ConfigFile.h"

namespace stairmap::apps {

namespace {

const char* kEvalHelp =
    "Inputs are files or directories. With --detect they are clouds (.pcd/.ply/.xyz, or .gz) with a\n"
    "<stem>.gt.json next to it (directories: every such cloud); the detector runs on each (floor\n"
    "height from the truth unless --estimate-floor) and its run time is reported. Without --detect\n"
    "they are detection JSON files (the output of `stairmap detect`, or a landmarks.json from\n"
    "`stairmap map`), each scored against <stem>.gt.json next to it or against --gt (one --gt for\n"
    "all inputs, or one per input: `eval a/landmarks.json b/landmarks.json --gt A/gt.json --gt\n"
    "B/gt.json` scores several maps into one table; a map's time/det comes from its stats.json).\n"
    "A detection matches a true staircase of the same direction-as-seen when the median horizontal\n"
    "distance of its edge centres to the nearest true nosing is < --max-xy and the median vertical\n"
    "distance < --max-z; each truth is matched at most once; other detections are false positives.\n"
    "A false positive meeting the direction and --max-xy for some true staircase lies on a true\n"
    "flight (its heights misread, or the flight read twice): counted apart, after the table.\n"
    "--perturb-m A (with --detect) moves every coordinate by a uniform offset in [-A, A] before\n"
    "detecting: another realisation of the same scenes (A = 1e-5 is far below any sensor noise but\n"
    "breaks the exact ties of clouds written on a lattice). Scores that move between realisations\n"
    "(--perturb-seed 1, 2, ...) show the evaluation's noise floor.\n"
    "Exit status: 0 on success, 2 on bad input (one line on stderr naming the file).";

struct EvalOptions {
    std::vector<std::string> inputs;
    std::vector<std::string> gt_paths;
    bool confirmed_only = false;
    bool run_detector = false;
    bool estimate_floor = false;
    std::string config_path;
    bool json = false;
    std::string group_by = "kind";
    double perturb_m = 0.0;        ///< [m] --detect: each coordinate moved by up to this (0: off)
    std::uint64_t perturb_seed = 1;
    EvaluationParams params;
};

DetectorParams detectorParams(const std::string& config_path) {
    if (config_path.empty()) return {};
    return io::loadDetectorConfigFile(config_path).params;
}

std::vector<EvaluationSample> detectSamples(const EvalOptions& options) {
    const StairDetector detector(detectorParams(options.config_path));
    std::vector<EvaluationSample> samples;
    for (const auto& cloud_path : io::findCloudsWithTruth(options.inputs)) {
        EvaluationSample sample;
        sample.name = cloud_path;
        const std::string gt = io::truthPathFor(cloud_path);
        sample.truth = io::readGroundTruthFile(gt);
        sample.kind = io::sampleLabel(gt, options.group_by);
        PointCloud cloud = io::readCloudFile(cloud_path);
        // The file name, not the path: a set's realisation does not depend on where it lies.
        perturbCloud(cloud, options.perturb_m, options.perturb_seed,
                     perturbationStream(std::filesystem::path(cloud_path).filename().string()));
        const std::optional<double> floor_z =
            options.estimate_floor ? std::nullopt : sample.truth.observer_floor_z;
        const auto start = std::chrono::steady_clock::now();
        sample.detections = detector.detect(cloud, floor_z).staircases;
        sample.time_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        samples.push_back(std::move(sample));
    }
    return samples;
}

int runEval(const EvalOptions& options) {
    std::vector<EvaluationSample> samples;
    if (options.run_detector) {
        samples = detectSamples(options);
    } else {
        io::DetectionLoadOptions load;
        load.confirmed_only = options.confirmed_only;
        const auto pairs = io::pairDetectionFilesWithTruth(options.inputs, options.gt_paths);
        for (const auto& [file, gt] : pairs)
            samples.push_back(io::loadDetectionSample(file, gt, load));
    }
    if (samples.empty()) throw std::runtime_error("no inputs with ground truth found");
    const auto report = evaluate(samples, options.params);
    const bool perturbed = options.run_detector && options.perturb_m > 0;
    if (options.json) {
        auto j = io::evaluationToJson(report, options.params);
        if (perturbed)
            j["perturbation"] = {{"amplitude_m", options.perturb_m}, {"seed", options.perturb_seed}};
        std::cout << j.dump(1) << "\n";
    } else {
        if (perturbed)
            std::cout << "perturbed realisation: every coordinate moved by up to "
                      << options.perturb_m << " m (seed " << options.perturb_seed << ")\n";
        std::cout << io::formatEvaluationTable(report);
        for (const auto& s : report.samples) {
            for (const auto& missed : s.missed) std::cout << "missed: " << s.name << " " << missed << "\n";
            if (s.false_positives > 0)
                std::cout << "false positives: " << s.name << " " << s.false_positives << " ("
                          << s.false_positives_on_flights << " on a true flight)\n";
        }
    }
    return 0;
}

}  // namespace

Command addEvalCommand(CLI::App& app) {
    auto options = std::make_shared<EvalOptions>();
    Command command;
    command.cli = app.add_subcommand("eval", "Score detections or a landmark map against gt.json");
    command.cli->footer(kEvalHelp);
    command.cli->add_option("inputs", options->inputs, "Detection JSONs, clouds (--detect) or directories")
        ->required();
    CLI::Option* detect =
        command.cli->add_flag("--detect", options->run_detector, "Run the detector on clouds first");
    command.cli->add_option("--gt", options->gt_paths,
                            "Ground truth: once for every input, or once per input in the same order "
                            "(several maps in one table); default <stem>.gt.json")
        ->allow_extra_args(false);
    command.cli->add_flag("--confirmed-only", options->confirmed_only,
                          "Landmark maps: score confirmed landmarks only");
    command.cli->add_flag("--estimate-floor", options->estimate_floor,
                          "--detect: let the detector estimate the floor instead of using the truth's");
    command.cli->add_option("--config", options->config_path, "INI file with a [detector] section");
    command.cli->add_flag("--json", options->json, "Machine-readable JSON instead of the table");
    command.cli->add_option("--group-by", options->group_by,
                            "--detect: table rows by this top-level gt.json key (default kind; e.g. "
                            "sensor_kind for the random benchmark)");
    command.cli
        ->add_option("--perturb-m", options->perturb_m,
                     "[m] --detect: move every coordinate by a uniform offset up to this before "
                     "detecting (another realisation of the same scenes; 0 = off)")
        ->check(CLI::Range(0.0, kMaxPerturbationM))
        ->needs(detect);
    command.cli
        ->add_option("--perturb-seed", options->perturb_seed,
                     "--detect: seed of the --perturb-m offsets (each cloud its own stream)")
        ->needs(detect);
    command.cli->add_option("--max-xy", options->params.max_xy_m, "[m] matching: median xy distance")
        ->check(CLI::PositiveNumber);
    command.cli->add_option("--max-z", options->params.max_z_m, "[m] matching: median z distance")
        ->check(CLI::PositiveNumber);
    command.run = [options, input = command.input]() {
        for (const auto& path : options->inputs) *input += (input->empty() ? "" : ", ") + path;
        return runEval(*options);
    };
    return command;
}

}  // namespace stairmap::apps
