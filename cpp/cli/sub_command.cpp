// `ubii-node sub PATTERN`: prints the records of a topic (or of every topic a regex matches).
#include <iostream>
#include <memory>
#include <sstream>

#include "cli_error.hpp"
#include "commands.hpp"
#include "message_output.hpp"

namespace ubii::cli
{

namespace
{

struct SubOptions {
    std::string pattern;
    bool regex = false;
    bool json = false;
    unsigned count = 0;
    double timeout_s = 0;
};

void print(const ubii::Record &record, bool json)
{
    const ubii::TopicDataRecord message = ubii::message_from_record(record);
    if (json) {
        std::cout << record_json(message).dump() << std::endl;
        return;
    }
    const RecordText text = record_text(message);
    std::cout << message.topic() << ' ' << text.type << ' ' << text.value << std::endl;
}

std::string seconds_text(double seconds)
{
    std::ostringstream text;
    text << seconds;
    return text.str();
}

int subscribe(Context &context, const SubOptions &options)
{
    if (options.timeout_s < 0 || options.timeout_s > 86400)
        throw CliError(exit_usage, "--timeout must be between 0 and 86400 seconds");
    const auto deadline =
        options.timeout_s > 0
            ? std::chrono::steady_clock::now() +
                  std::chrono::milliseconds(static_cast<long long>(options.timeout_s * 1000))
            : std::chrono::steady_clock::time_point::max();
    ubii::Node node = connect(context.connection);
    unsigned received = 0;
    const auto on_record = [&](const ubii::Record &record) {
        if (options.count > 0 && received >= options.count)
            return;
        ++received;
        print(record, options.json);
    };
    ubii::Subscription subscription;
    try {
        subscription = options.regex ? node.subscribe_regex(options.pattern, on_record)
                                     : node.subscribe(options.pattern, on_record);
    } catch (const ubii::Error &error) {
        throw CliError(exit_usage, "cannot subscribe to " + options.pattern + ": " + error.what());
    }
    if (!node.run_until([&] { return !node.subscriptions_pending() || interrupted(); },
                        context.connection.timeout()) &&
        !interrupted())
        throw CliError(exit_timeout,
                       "the master did not confirm the subscription to " + options.pattern);
    if (context.verbosity > 0)
        std::cerr << "ubii-node: subscribed to " << options.pattern << std::endl;
    while (!interrupted() && (options.count == 0 || received < options.count)) {
        if (std::chrono::steady_clock::now() >= deadline)
            break;
        if (node.state() == ubii::ConnectionState::failed)
            throw CliError(exit_no_master, "lost the master: " + node.transport_error());
        node.poll(std::chrono::milliseconds(100));
    }
    if (options.count > 0 && received < options.count && !interrupted())
        throw CliError(exit_timeout, "received " + std::to_string(received) + " of " +
                                         std::to_string(options.count) + " records on " +
                                         options.pattern + " within " +
                                         seconds_text(options.timeout_s) + " s");
    return exit_ok;
}

} // namespace

void add_sub_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand(
        "sub", "Print the records published on a topic, one line each (images summarised)");
    auto options = std::make_shared<SubOptions>();
    command->add_option("PATTERN", options->pattern, "the topic (a regex with --regex)")
        ->required();
    command->add_flag("--regex", options->regex, "PATTERN is a regular expression");
    command->add_flag("--json", options->json, "one JSON object per record");
    command->add_option("--count", options->count, "stop after this many records (0: never)");
    command->add_option("--timeout", options->timeout_s,
                        "stop after this many seconds; with --count, fewer records exit with 4");
    command->callback([&context, options] {
        context.action = [&context, options] { return subscribe(context, *options); };
    });
}

} // namespace ubii::cli
