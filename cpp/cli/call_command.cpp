// `ubii-node call SERVICE [--json REQUEST]`: any service of the master, the reply as JSON.
#include <iostream>
#include <memory>

#include <google/protobuf/util/json_util.h>

#include "cli_error.hpp"
#include "commands.hpp"
#include "message_output.hpp"

namespace ubii::cli
{

namespace
{

ubii::ServiceRequest make_request(const std::string &service, const std::string &json)
{
    ubii::ServiceRequest request;
    if (!json.empty()) {
        const auto status = google::protobuf::util::JsonStringToMessage(json, &request);
        if (!status.ok())
            throw CliError(exit_usage, "the request is not a ServiceRequest in JSON: " +
                                           std::string(status.message()));
    }
    request.set_topic(service);
    return request;
}

} // namespace

void add_call_command(CLI::App &app, Context &context)
{
    CLI::App *command =
        app.add_subcommand("call", "Call a service of the master and print its reply as JSON");
    auto service = std::make_shared<std::string>();
    auto request_json = std::make_shared<std::string>();
    command->add_option("SERVICE", *service, "the service topic, e.g. /services/topic_list")
        ->required();
    command->add_option("--json", *request_json,
                        "the request: a ServiceRequest in proto3 JSON without its topic, e.g. "
                        "'{\"stringList\": {\"elements\": [\"/a\"]}}'");
    command->callback([&context, service, request_json] {
        context.action = [&context, service, request_json] {
            const ubii::ServiceRequest request = make_request(*service, *request_json);
            ubii::Node node = connect(context.connection);
            const ubii::ServiceReply reply =
                await(node, node.call(request), context.connection.timeout());
            std::cout << to_json(reply).dump(2) << '\n';
            return int(exit_ok);
        };
    });
}

} // namespace ubii::cli
