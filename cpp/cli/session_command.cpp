// `ubii-node session start FILE | stop ID | list`: sessions from JSON spec files.
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <google/protobuf/util/json_util.h>

#include "cli_error.hpp"
#include "commands.hpp"
#include "message_output.hpp"

namespace ubii::cli
{

namespace
{

ubii::Session read_session(const std::string &path)
{
    std::ifstream file(path);
    if (!file)
        throw CliError(exit_usage, "cannot read the session spec " + path);
    std::stringstream text;
    text << file.rdbuf();
    ubii::Session session;
    const auto status = google::protobuf::util::JsonStringToMessage(text.str(), &session);
    if (!status.ok())
        throw CliError(exit_usage, path + " is not a ubii.sessions.Session in JSON: " +
                                       std::string(status.message()));
    return session;
}

void print_session(const ubii::Session &session, bool json)
{
    if (json)
        std::cout << to_json(session).dump(2) << '\n';
    else
        std::cout << session.id() << ' ' << ubii::sessions::SessionStatus_Name(session.status())
                  << ' ' << session.name() << '\n';
}

} // namespace

void add_session_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand("session", "Start, stop and list sessions");
    command->require_subcommand(1);
    auto json = std::make_shared<bool>(false);
    command->add_flag("--json", *json, "print the sessions as JSON");

    CLI::App *start = command->add_subcommand(
        "start", "Start a session from a JSON spec file (ubii.sessions.Session in proto3 JSON); "
                 "prints its id, status and name");
    auto spec_file = std::make_shared<std::string>();
    start->add_option("FILE", *spec_file, "the session spec")->required();
    start->callback([&context, spec_file, json] {
        context.action = [&context, spec_file, json] {
            const ubii::Session spec = read_session(*spec_file);
            ubii::Node node = connect(context.connection);
            print_session(await(node, node.sessions().start(spec), context.connection.timeout()),
                          *json);
            return int(exit_ok);
        };
    });

    CLI::App *stop = command->add_subcommand("stop", "Stop the session ID; prints it afterwards");
    auto id = std::make_shared<std::string>();
    stop->add_option("ID", *id, "the session's id")->required();
    stop->callback([&context, id, json] {
        context.action = [&context, id, json] {
            ubii::Node node = connect(context.connection);
            print_session(await(node, node.sessions().stop(*id), context.connection.timeout()),
                          *json);
            return int(exit_ok);
        };
    });

    CLI::App *list = command->add_subcommand("list", "List the sessions the master runs");
    list->callback([&context, json] {
        context.action = [&context, json] {
            ubii::Node node = connect(context.connection);
            const ubii::SessionList sessions =
                await(node, node.sessions().list(), context.connection.timeout());
            for (const ubii::Session &session : sessions.elements())
                print_session(session, *json);
            return int(exit_ok);
        };
    });
}

} // namespace ubii::cli
