// ubii-node: a command-line Ubi-Interact node (README.md, "The ubii-node command").
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli_error.hpp"
#include "commands.hpp"
#include "ubii/version.h"

int main(int argc, char **argv)
{
    using namespace ubii::cli;
    CLI::App app("ubii-node: look into a running Ubi-Interact network, publish and subscribe, "
                 "call services, control sessions, and serve processing modules from plugins",
                 "ubii-node");
    app.set_version_flag("--version", std::string("ubii-node (libubii) ") + ubii_version());
    app.require_subcommand(1);
    app.fallthrough();
    Context context;
    add_connection_options(app, context.connection);
    app.add_flag("-v,--verbose", context.verbosity, "say more (on stderr; run: errors too)");
    add_info_command(app, context);
    add_list_command(app, context);
    add_pub_command(app, context);
    add_sub_command(app, context);
    add_call_command(app, context);
    add_session_command(app, context);
    add_modules_command(app, context);
    add_run_command(app, context);
    add_ocr_command(app, context);

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success &success) {
        return app.exit(success);
    } catch (const CLI::ParseError &error) {
        app.exit(error);
        return exit_usage;
    } catch (const CliError &error) { // raised while parsing, by an option's own check
        std::cerr << "ubii-node: " << error.what() << '\n';
        return error.code();
    }

    install_signal_handlers();
    try {
        return context.action();
    } catch (const CliError &error) {
        if (error.code() != exit_ok)
            std::cerr << "ubii-node: " << error.what() << '\n';
        return error.code();
    } catch (const ubii::Error &error) {
        std::cerr << "ubii-node: " << error.what() << '\n';
        return exit_master_error;
    } catch (const std::exception &error) {
        std::cerr << "ubii-node: unexpected error: " << error.what() << '\n';
        return exit_master_error;
    }
}
