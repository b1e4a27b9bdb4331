// `ubii-node pub TOPIC VALUE`: publishes one record, or --count of them at --rate; or an image
// file as an Image2D.
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "cli_error.hpp"
#include "commands.hpp"
#include "image_file.hpp"
#include "record_input.hpp"
#include "ubii/config.h"

namespace ubii::cli
{

namespace
{

struct PubOptions {
    std::string topic;
    std::string value;
    std::string type = "auto";
    std::string image_file;
    double rate_hz = 10;
    unsigned count = 1;
    double linger_s = 0.5;
};

// The records to publish, made before connecting: a bad value fails without a master.
ubii::Record make_record(const PubOptions &options)
{
    if (!options.image_file.empty())
        return ubii::Record(options.topic, ubii::Value(read_image_file(options.image_file)));
    if (options.value.empty() && options.type != "string")
        throw CliError(exit_usage, "pub needs a VALUE (or --image FILE)");
    return ubii::record_from_message(parse_record(options.topic, options.type, options.value));
}

int publish(Context &context, const PubOptions &options)
{
    if (!(options.rate_hz > 0) || options.rate_hz > 10000)
        throw CliError(exit_usage, "--rate must be between 0 and 10000 Hz");
    if (options.linger_s < 0 || options.linger_s > 60)
        throw CliError(exit_usage, "--linger must be between 0 and 60 seconds");
    const ubii::Record record = make_record(options);
    ubii::Node node = connect(context.connection);
    const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(1.0 / options.rate_hz));
    auto next = std::chrono::steady_clock::now();
    for (unsigned sent = 0; sent < options.count && !interrupted(); ++sent) {
        if (sent > 0) {
            next += period;
            node.run_until(
                [&] { return interrupted() || std::chrono::steady_clock::now() >= next; },
                std::chrono::duration_cast<std::chrono::milliseconds>(period) +
                    std::chrono::milliseconds(1));
        }
        const ubii::Status status = node.try_publish(record);
        if (status == ubii::Status::too_large)
            throw CliError(exit_usage, "the record on " + options.topic +
                                           " is larger than the largest message a node sends (" +
                                           std::to_string(UBII_MAX_MESSAGE_SIZE >> 20) +
                                           " MiB, UBII_MAX_MESSAGE_SIZE)");
        if (status != ubii::Status::ok)
            throw CliError(status == ubii::Status::not_connected ? exit_no_master : exit_usage,
                           "cannot publish on " + options.topic + ": " + ubii::describe(status));
        if (context.verbosity > 0)
            std::cerr << "ubii-node: published " << sent + 1 << " of " << options.count << '\n';
    }
    // The master reads records and service requests on different sockets: a record still on
    // its way when the deregistration arrives would be dropped with the client.
    node.run_for(std::chrono::milliseconds(static_cast<long long>(options.linger_s * 1000)));
    return exit_ok;
}

} // namespace

void add_pub_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand("pub", "Publish a record on a topic");
    auto options = std::make_shared<PubOptions>();
    command->add_option("TOPIC", options->topic, "the topic")->required();
    command->add_option("VALUE", options->value, "the value, as --type reads it");
    command
        ->add_option("--type", options->type,
                     "the record member: auto (double, bool or string), json (a "
                     "TopicDataRecord), or a member such as double, string, vector3")
        ->check(CLI::IsMember(record_type_names()))
        ->capture_default_str();
    command->add_option("--image", options->image_file,
                        "publish this image file as an Image2D (PNG, JPEG, ...)");
    command->add_option("--count", options->count, "how many records")->capture_default_str();
    command->add_option("--rate", options->rate_hz, "records per second with --count")
        ->capture_default_str();
    command
        ->add_option("--linger", options->linger_s,
                     "seconds to stay connected after the last record, so that the master "
                     "takes it in before this client leaves")
        ->capture_default_str();
    command->callback([&context, options] {
        context.action = [&context, options] { return publish(context, *options); };
    });
}

} // namespace ubii::cli
