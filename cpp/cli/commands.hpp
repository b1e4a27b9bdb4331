#ifndef UBII_CLI_COMMANDS_HPP
#define UBII_CLI_COMMANDS_HPP

// The commands of `ubii-node`, each in its own file: add_*_command registers the command and its
// options on the app; when the command line chooses it, it sets Context::action, which main() runs
// after parsing and whose result is the exit code.

#include <functional>

#include <CLI/CLI.hpp>

#include "connection.hpp"

namespace ubii::cli
{

struct Context {
    ConnectionOptions connection;
    int verbosity = 0;
    std::function<int()> action;
};

void add_info_command(CLI::App &app, Context &context);
void add_list_command(CLI::App &app, Context &context);
void add_pub_command(CLI::App &app, Context &context);
void add_sub_command(CLI::App &app, Context &context);
void add_call_command(CLI::App &app, Context &context);
void add_session_command(CLI::App &app, Context &context);
void add_modules_command(CLI::App &app, Context &context);
void add_run_command(CLI::App &app, Context &context);
void add_ocr_command(CLI::App &app, Context &context);

} // namespace ubii::cli

#endif
