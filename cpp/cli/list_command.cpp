// `ubii-node list KIND`: what the master knows, as a table or JSON.
#include <iostream>
#include <map>
#include <memory>

#include "cli_error.hpp"
#include "commands.hpp"
#include "message_output.hpp"

namespace ubii::cli
{

namespace
{

struct Listing {
    // The master's reply; its elements are the rows.
    std::unique_ptr<google::protobuf::Message> reply;
    std::vector<std::string> columns;
};

template <class T>
Listing listing(ubii::Node &node, const ubii::Call<T> &call, std::chrono::milliseconds timeout,
                std::vector<std::string> columns)
{
    return Listing{std::make_unique<T>(await(node, call, timeout)), std::move(columns)};
}

Listing fetch(ubii::Node &node, const std::string &kind, std::chrono::milliseconds timeout)
{
    ubii::Master master = node.master();
    if (kind == "services")
        return listing(node, master.services(), timeout,
                       {"topic", "request_message_format", "response_message_format"});
    if (kind == "topics")
        return listing(node, master.topics(), timeout, {});
    if (kind == "clients")
        return listing(node, master.clients(), timeout,
                       {"id", "name", "state", "is_dedicated_processing_node", "host_ip",
                        "processing_modules"});
    if (kind == "devices")
        return listing(node, master.devices(), timeout,
                       {"id", "name", "device_type", "client_id", "components"});
    if (kind == "sessions")
        return listing(node, node.sessions().list(), timeout,
                       {"id", "name", "status", "processing_modules", "io_mappings"});
    return listing(node, master.processing_modules(), timeout,
                   {"name", "id", "language", "node_id", "session_id", "status"});
}

} // namespace

void add_list_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand(
        "list", "List the master's services, topics, clients, devices, sessions or processing "
                "modules");
    auto kind = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    command->add_option("KIND", *kind, "what to list")
        ->required()
        ->check(CLI::IsMember({"services", "topics", "clients", "devices", "sessions", "modules"}));
    command->add_flag("--json", *json, "print a JSON array");
    command->callback([&context, kind, json] {
        context.action = [&context, kind, json] {
            ubii::Node node = connect(context.connection);
            const Listing list = fetch(node, *kind, context.connection.timeout());
            const auto *elements = list.reply->GetDescriptor()->FindFieldByName("elements");
            const auto *reflection = list.reply->GetReflection();
            nlohmann::ordered_json array = nlohmann::ordered_json::array();
            if (list.columns.empty()) { // a list of strings
                for (int i = 0; i < reflection->FieldSize(*list.reply, elements); ++i) {
                    const std::string element =
                        reflection->GetRepeatedString(*list.reply, elements, i);
                    if (*json)
                        array.push_back(element);
                    else
                        std::cout << element << '\n';
                }
            } else {
                std::vector<const google::protobuf::Message *> rows;
                for (int i = 0; i < reflection->FieldSize(*list.reply, elements); ++i)
                    rows.push_back(&reflection->GetRepeatedMessage(*list.reply, elements, i));
                if (*json)
                    for (const auto *row : rows)
                        array.push_back(to_json(*row));
                else
                    print_table(rows, list.columns);
            }
            if (*json)
                std::cout << array.dump(2) << '\n';
            return int(exit_ok);
        };
    });
}

} // namespace ubii::cli
