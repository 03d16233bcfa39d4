// stairmap: one executable, one subcommand per job (detect, sim, eval, map).

#include <exception>
#include <iostream>
#include <vector>

#include "Commands.h"

int main(int argc, char** argv) {
    using namespace stairmap::apps;
    CLI::App app{
        "stairmap: find, measure and map staircases in 3D LiDAR data (MRPT rawlogs, PCD/PLY/XYZ).\n"
        "Run `stairmap <command> --help` for the options of each command."};
    app.require_subcommand(1);
    std::vector<Command> commands = {addDetectCommand(app), addSimCommand(app),
                                     addEvalCommand(app), addMapCommand(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help exits 0; every usage error exits 2.
        return app.exit(e) == 0 ? 0 : 2;
    }
    for (const Command& command : commands) {
        if (!command.cli->parsed()) continue;
        try {
            return command.run();
        } catch (const std::exception& e) {
            std::cerr << "stairmap " << command.cli->get_name() << ": error: " << e.what() << "\n";
            return 2;
        }
    }
    return 2;
}
