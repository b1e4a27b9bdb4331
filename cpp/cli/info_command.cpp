// `ubii-node info`: the master's server configuration.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "message_output.hpp"

namespace ubii::cli
{

namespace
{
constexpr std::size_t max_text_value = 120;
}

void add_info_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand("info", "Show the master's server configuration");
    auto json = std::make_shared<bool>(false);
    command->add_flag("--json", *json, "print JSON");
    command->callback([&context, json] {
        context.action = [&context, json] {
            ubii::Node node = connect(context.connection);
            const ubii::Server server =
                await(node, node.master().server_configuration(), context.connection.timeout());
            const nlohmann::ordered_json fields = to_json(server);
            if (*json) {
                std::cout << fields.dump(2) << '\n';
                return int(exit_ok);
            }
            for (const auto &field : fields.items()) {
                std::string value = field.value().is_string() ? field.value().get<std::string>()
                                                              : field.value().dump();
                // constantsJson runs to kilobytes: people get its size, scripts --json.
                if (value.size() > max_text_value)
                    value = "<" + std::to_string(value.size()) + " characters; --json shows it>";
                std::cout << field.key() << ": " << value << '\n';
            }
            return int(exit_ok);
        };
    });
}

} // namespace ubii::cli
