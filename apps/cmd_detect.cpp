// TODO: placeholder, replaced by the real `stairmap detect`.
#include <stdexcept>

#include "Commands.h"

namespace stairmap::apps {

Command addDetectCommand(CLI::App& app) {
    Command command;
    command.cli = app.add_subcommand("detect", "(not implemented yet)");
    command.run = []() -> int { throw std::runtime_error("'detect' is not implemented yet"); };
    return command;
}

}  // namespace stairmap::apps
