// TODO: placeholder, replaced by the real `stairmap sim`.
#include <stdexcept>

#include "Commands.h"

namespace stairmap::apps {

Command addSimCommand(CLI::App& app) {
    Command command;
    command.cli = app.add_subcommand("sim", "(not implemented yet)");
    command.run = []() -> int { throw std::runtime_error("'sim' is not implemented yet"); };
    return command;
}

}  // namespace stairmap::apps
