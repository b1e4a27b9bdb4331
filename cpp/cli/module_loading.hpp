#ifndef UBII_CLI_MODULE_LOADING_HPP
#define UBII_CLI_MODULE_LOADING_HPP

// The processing modules `run` offers and `modules` lists: those linked into ubii-node, and the
// plugins in --modules DIRs, UBII_MODULE_PATH and the installation's lib/ubii/modules.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "ubii/ubii.hpp"

namespace ubii::cli
{

struct ModuleOptions {
    std::vector<std::string> dirs;
    // Only `dirs`: not UBII_MODULE_PATH nor the installation's plugins.
    bool only_given_dirs = false;
    // NAME:key=value
    std::vector<std::string> arguments;
};
void add_module_options(CLI::App &command, ModuleOptions &options);

struct LoadedModules {
    ubii::ModuleRegistry registry;
    std::vector<ubii::PluginReport> reports;
    std::vector<std::string> searched;
    std::size_t refusals() const;
    // The directories looked in, for messages: "a, b", or "no directory".
    std::string searched_text() const;
};

// Loads everything and prints each refusal on stderr ("ubii-node: FILE: why"). A --modules DIR
// that does not exist is CliError(exit_usage). With `names`, keeps those modules only
// (CliError(exit_modules) for one not found). Then hands each module its --module-arg values
// (CliError(exit_usage) for a malformed one, one naming an unknown module, or one its module
// refuses).
LoadedModules load_modules(const ModuleOptions &options, const std::vector<std::string> &names);

} // namespace ubii::cli

#endif
