// `ubii-node modules`: the processing modules this ubii-node would offer, without a master; the
// way to check that a plugin loads (exit 5 when anything was refused).
#include <iostream>
#include <memory>

#include "cli_error.hpp"
#include "commands.hpp"
#include "message_output.hpp"
#include "module_loading.hpp"

namespace ubii::cli
{

namespace
{

std::string source_of(const LoadedModules &loaded, const std::string &module)
{
    for (const auto &report : loaded.reports)
        for (const std::string &name : report.modules)
            if (name == module)
                return report.file.string();
    return "";
}

int list_modules(const ModuleOptions &options, bool json)
{
    const LoadedModules loaded = load_modules(options, {});
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    std::vector<const google::protobuf::Message *> rows;
    for (const std::string &name : loaded.registry.names()) {
        const ubii::ProcessingModuleSpec &spec = loaded.registry.spec(name);
        if (json) {
            nlohmann::ordered_json entry = to_json(spec);
            entry["file"] = source_of(loaded, name);
            array.push_back(std::move(entry));
        }
        rows.push_back(&spec);
    }
    if (json)
        std::cout << array.dump(2) << '\n';
    else if (!rows.empty())
        print_table(rows, {"name", "inputs", "outputs", "processing_mode", "description"});
    if (!json && loaded.registry.empty())
        std::cerr << "ubii-node: no processing modules (looked in: " << loaded.searched_text()
                  << ")\n";
    return loaded.refusals() > 0 ? exit_modules : exit_ok;
}

} // namespace

void add_modules_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand(
        "modules", "List the processing modules found here (linked and plugins), no master "
                   "needed; exits with 5 if a plugin or module was refused");
    auto options = std::make_shared<ModuleOptions>();
    auto json = std::make_shared<bool>(false);
    add_module_options(*command, *options);
    command->add_flag("--json", *json, "print a JSON array of the modules' specs");
    command->callback([&context, options, json] {
        context.action = [options, json] { return list_modules(*options, *json); };
    });
}

} // namespace ubii::cli
