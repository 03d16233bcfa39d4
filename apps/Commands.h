#pragma once
// Each `stairmap` subcommand lives in its own file and registers itself on the CLI11 app.

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>

namespace stairmap::apps {

/// A registered subcommand: its CLI11 node and what to run when it was chosen.
/// `run` returns the process exit code; exceptions it throws become "error: ..." and exit 2.
/// `input` names the file being processed (the command updates it as it goes), for the errors that
/// cannot name it themselves: running out of memory (std::bad_alloc) and unknown exceptions.
struct Command {
    CLI::App* cli = nullptr;
    std::function<int()> run;
    std::shared_ptr<std::string> input = std::make_shared<std::string>();
};

Command addDetectCommand(CLI::App& app);
Command addSimCommand(CLI::App& app);
Command addEvalCommand(CLI::App& app);
Command addMapCommand(CLI::App& app);
Command addMergeCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);
Command addAnnotateCommand(CLI::App& app);
Command addLiveCommand(CLI::App& app);
Command addPlayCommand(CLI::App& app);
Command addFleetCommand(CLI::App& app);

}  // namespace stairmap::apps
