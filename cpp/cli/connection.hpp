#ifndef UBII_CLI_CONNECTION_HPP
#define UBII_CLI_CONNECTION_HPP

// The options every command that talks to a master shares, and the node they make.

#include <chrono>
#include <string>

#include <CLI/CLI.hpp>

#include "cli_error.hpp"
#include "ubii/ubii.hpp"

namespace ubii::cli
{

struct ConnectionOptions {
    std::string service_url = "tcp://127.0.0.1:8101";
    std::string topic_url;
    std::string name = "ubii-node";
    double connect_timeout_s = 5;
    double timeout_s = 5;

    std::chrono::milliseconds connect_timeout() const;
    std::chrono::milliseconds timeout() const;
    ubii::NodeOptions node_options() const;
};

// Adds --service-url, --topic-url, --name, --connect-timeout, --reply-timeout (every command).
void add_connection_options(CLI::App &app, ConnectionOptions &options);

// Connects `node`: CliError(exit_no_master) when the master is not reachable within `timeout`.
void connect(ubii::Node &node, std::chrono::milliseconds timeout);
// A node with these options, connected within --connect-timeout (the same errors).
ubii::Node connect(const ConnectionOptions &options);

// SIGINT and SIGTERM end a command's loop; SIGUSR1 asks `run` for its timing report.
void install_signal_handlers();
bool interrupted() noexcept;
// True once per SIGUSR1 received since the last call.
bool take_report_request() noexcept;

[[noreturn]] void throw_call_failure(const std::string &service);

// Waits for a call's reply: CliError with exit_master_error for the master's error reply,
// exit_timeout for none within --reply-timeout (+1 s for the node's own timer to fire).
template <class T>
T await(ubii::Node &node, const ubii::Call<T> &call, std::chrono::milliseconds timeout)
{
    node.run_until([&call] { return call.done() || interrupted(); },
                   timeout + std::chrono::seconds(1));
    if (!call.done())
        throw CliError(interrupted() ? exit_ok : exit_timeout,
                       interrupted() ? "interrupted" : "no reply from " + call.service());
    try {
        return call.get();
    } catch (...) {
        throw_call_failure(call.service());
    }
}

} // namespace ubii::cli

#endif
