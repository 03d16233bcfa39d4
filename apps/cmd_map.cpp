// TODO: placeholder, replaced by the real `stairmap map`.
#include <stdexcept>

#include "Commands.h"

namespace stairmap::apps {

Command addMapCommand(CLI::App& app) {
    Command command;
    command.cli = app.add_subcommand("map", "(not implemented yet)");
    command.run = []() -> int { throw std::runtime_error("'map' is not implemented yet"); };
    return command;
}

}  // namespace stairmap::apps
