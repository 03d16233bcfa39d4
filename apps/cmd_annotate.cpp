// `stairmap annotate`: a copy of a rawlog with a 3D scene of stairmap's results after each
// detector run (for MRPT's RawLogViewer).
#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "io/annotate/RawlogAnnotator.h"

namespace stairmap::apps {

Command addAnnotateCommand(CLI::App& app) {
    auto opt = std::make_shared<io::AnnotateOptions>();
    Command command;
    command.cli = app.add_subcommand(
        "annotate", "Copy a rawlog, inserting after each detector run a CObservation3DScene\n"
                    "(sensor label 'stairmap') with that run's detections and the landmarks so\n"
                    "far; every other object is copied unchanged. Open OUT in RawLogViewer.\n"
                    "Exit codes: 0 ok; 2 bad arguments/input (also a truncated or corrupt log).");
    command.cli->add_option("in", opt->in, "input rawlog")->required()->check(CLI::ExistingFile);
    command.cli->add_option("out", opt->out, "output rawlog")->required();
    command.cli->add_option("--poses", opt->poses, "TUM trajectory (as for `stairmap map`)")
        ->check(CLI::ExistingFile);
    command.cli->add_option("--config", opt->config, "INI file (as for `stairmap map`)");
    command.run = [opt]() -> int {
        const io::AnnotateStats s = io::annotateRawlog(*opt);
        std::printf("stairmap annotate: %zu objects copied, %zu scenes inserted (%zu detector runs, "
                    "%zu detections) -> %s\n", s.objects_copied, s.scenes_inserted, s.detector_runs,
                    s.detections, opt->out.c_str());
        return 0;
    };
    return command;
}

}  // namespace stairmap::apps
