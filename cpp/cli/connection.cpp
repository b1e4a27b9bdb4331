#include "connection.hpp"

#include <csignal>

#include "cli_error.hpp"

namespace ubii::cli
{

namespace
{

volatile std::sig_atomic_t stop_requested = 0;
volatile std::sig_atomic_t report_requested = 0;

extern "C" void on_stop_signal(int)
{
    stop_requested = 1;
}

extern "C" void on_report_signal(int)
{
    report_requested = 1;
}

std::chrono::milliseconds from_seconds(double seconds, const char *option)
{
    if (!(seconds > 0) || seconds > 86400)
        throw CliError(exit_usage, std::string(option) + " must be between 0 and 86400 seconds");
    return std::chrono::milliseconds(static_cast<long long>(seconds * 1000));
}

} // namespace

std::chrono::milliseconds ConnectionOptions::connect_timeout() const
{
    return from_seconds(connect_timeout_s, "--connect-timeout");
}

std::chrono::milliseconds ConnectionOptions::timeout() const
{
    return from_seconds(timeout_s, "--reply-timeout");
}

ubii::NodeOptions ConnectionOptions::node_options() const
{
    ubii::NodeOptions options;
    options.service_url = service_url;
    options.topic_url = topic_url;
    options.name = name;
    options.service_timeout = timeout();
    options.enable_tls = service_url.rfind("https://", 0) == 0 || topic_url.rfind("wss://", 0) == 0;
    // A command-line tool reports a lost master instead of retrying for ever.
    options.reconnect.max_attempts = 3;
    return options;
}

void add_connection_options(CLI::App &app, ConnectionOptions &options)
{
    app.add_option("--service-url", options.service_url,
                   "the master's service endpoint: tcp://HOST:8101 or "
                   "http(s)://HOST:8102/services/binary")
        ->envname("UBII_SERVICE_URL")
        ->capture_default_str();
    app.add_option("--topic-url", options.topic_url,
                   "the master's topic data endpoint: tcp://HOST:8103 or ws(s)://HOST:8104 "
                   "(default: ZMQ at the port the master names)")
        ->envname("UBII_TOPIC_URL");
    app.add_option("--name", options.name, "this node's client name")->capture_default_str();
    app.add_option("--connect-timeout", options.connect_timeout_s, "seconds to wait for the master")
        ->capture_default_str();
    app.add_option("--reply-timeout", options.timeout_s, "seconds to wait for each service reply")
        ->capture_default_str();
}

void connect(ubii::Node &node, std::chrono::milliseconds timeout)
{
    try {
        node.connect(timeout);
    } catch (const ubii::Error &error) {
        throw CliError(exit_no_master, error.what());
    }
}

ubii::Node connect(const ConnectionOptions &options)
{
    ubii::Node node(options.node_options());
    connect(node, options.connect_timeout());
    return node;
}

[[noreturn]] void throw_call_failure(const std::string &service)
{
    try {
        throw;
    } catch (const ubii::ServiceError &error) {
        throw CliError(exit_master_error, service + ": the master answered with an error: " +
                                              error.title() + ": " + error.message());
    } catch (const ubii::Timeout &error) {
        throw CliError(exit_timeout, error.what());
    } catch (const ubii::NotConnected &error) {
        throw CliError(exit_no_master, error.what());
    } catch (const ubii::TransportError &error) {
        throw CliError(exit_no_master, error.what());
    } catch (const ubii::Error &error) {
        throw CliError(exit_master_error, service + ": " + error.what());
    }
}

void install_signal_handlers()
{
    struct sigaction stop {
    };
    stop.sa_handler = on_stop_signal;
    sigemptyset(&stop.sa_mask);
    sigaction(SIGINT, &stop, nullptr);
    sigaction(SIGTERM, &stop, nullptr);
    struct sigaction report {
    };
    report.sa_handler = on_report_signal;
    sigemptyset(&report.sa_mask);
    report.sa_flags = SA_RESTART;
    sigaction(SIGUSR1, &report, nullptr);
}

bool interrupted() noexcept
{
    return stop_requested != 0;
}

bool take_report_request() noexcept
{
    if (report_requested == 0)
        return false;
    report_requested = 0;
    return true;
}

} // namespace ubii::cli
