// TODO: placeholder, replaced by the real `stairmap eval`.
#include <stdexcept>

#include "Commands.h"

namespace stairmap::apps {

Command addEvalCommand(CLI::App& app) {
    Command command;
    command.cli = app.add_subcommand("eval", "(not implemented yet)");
    command.run = []() -> int { throw std::runtime_error("'eval' is not implemented yet"); };
    return command;
}

}  // namespace stairmap::apps
