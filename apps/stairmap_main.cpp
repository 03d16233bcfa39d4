// stairmap: one executable, one subcommand per job (detect, sim, eval, map, merge, export, view,
// annotate, live, play, fleet).

#include <exception>
#include <new>
#include <iostream>
#include <string>
#include <vector>

#include "Commands.h"

namespace {

/// Runs the chosen command; every exception becomes one line on stderr and exit status 2.
int runCommand(const stairmap::apps::Command& command) {
    const std::string prefix = "stairmap " + command.cli->get_name() + ": error: ";
    const auto input = [&] { return command.input->empty() ? std::string("stairmap") : *command.input; };
    try {
        return command.run();
    } catch (const std::bad_alloc&) {
        std::cerr << prefix << input() << ": out of memory while processing this input\n";
    } catch (const std::exception& e) {
        std::cerr << prefix << e.what() << "\n";
    } catch (...) {
        std::cerr << prefix << input() << ": unexpected error while processing this input\n";
    }
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace stairmap::apps;
    CLI::App app{
        "stairmap: find, measure and map staircases in 3D LiDAR data (MRPT rawlogs, PCD/PLY/XYZ).\n"
        "Run `stairmap <command> --help` for the options of each command."};
    app.require_subcommand(1);
    std::vector<Command> commands = {addDetectCommand(app), addSimCommand(app),
                                     addEvalCommand(app), addMapCommand(app),
                                     addMergeCommand(app), addExportCommand(app),
                                     addViewCommand(app), addAnnotateCommand(app),
                                     addLiveCommand(app), addPlayCommand(app),
                                     addFleetCommand(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help prints the (sub)command's help and exits 0; every usage error is one line, exit 2.
        if (e.get_exit_code() == 0) return app.exit(e);
        std::string command = "stairmap";
        for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
        std::cerr << command << ": error: " << e.what() << " (see `" << command << " --help`)\n";
        return 2;
    }
    for (const Command& command : commands) {
        if (command.cli->parsed()) return runCommand(command);
    }
    return 2;
}
