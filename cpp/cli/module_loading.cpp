#include "module_loading.hpp"

#include <cstdlib>
#include <iostream>
#include <map>

#include "cli_error.hpp"
#include "message_output.hpp"

namespace ubii::cli
{

namespace
{

void add_report(LoadedModules &loaded, ubii::PluginReport report)
{
    for (const std::string &error : report.errors)
        std::cerr << "ubii-node: " << error << '\n';
    loaded.reports.push_back(std::move(report));
}

// NAME:key=value, grouped by module name.
std::map<std::string, ubii::ModuleArguments> parse_arguments(const std::vector<std::string> &given)
{
    std::map<std::string, ubii::ModuleArguments> arguments;
    for (const std::string &text : given) {
        const std::size_t colon = text.find(':');
        const std::size_t equals = text.find('=', colon == std::string::npos ? 0 : colon);
        if (colon == 0 || colon == std::string::npos || equals == std::string::npos ||
            equals == colon + 1)
            throw CliError(exit_usage, "--module-arg " + text + " is not NAME:key=value");
        arguments[text.substr(0, colon)].set(text.substr(colon + 1, equals - colon - 1),
                                             text.substr(equals + 1));
    }
    return arguments;
}

} // namespace

std::size_t LoadedModules::refusals() const
{
    std::size_t count = 0;
    for (const auto &report : reports)
        count += report.errors.size();
    return count;
}

std::string LoadedModules::searched_text() const
{
    return searched.empty() ? "no directory" : joined(searched);
}

void add_module_options(CLI::App &command, ModuleOptions &options)
{
    command
        .add_option("--modules", options.dirs,
                    "a directory of plugins (or one plugin file) to load; repeatable, looked "
                    "in before UBII_MODULE_PATH and the installation's lib/ubii/modules")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    command.add_flag("--no-default-modules", options.only_given_dirs,
                     "look only in the --modules DIRs, not in UBII_MODULE_PATH nor the "
                     "installation's lib/ubii/modules");
    command
        .add_option("--module-arg", options.arguments,
                    "NAME:key=value, an argument for module NAME's factory; repeatable")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

LoadedModules load_modules(const ModuleOptions &options, const std::vector<std::string> &names)
{
    LoadedModules loaded;
    // Tesseract's OpenMP runtime (the OCR plugin brings it) reads OMP_THREAD_LIMIT once, as it
    // loads: several threads make it several times slower on small machines (ocr/README.md,
    // "OpenMP"). Set before any plugin loads; a value the user chose is kept.
    setenv("OMP_THREAD_LIMIT", "1", 0);
    add_report(loaded, ubii::add_linked_modules(loaded.registry));
    std::vector<std::filesystem::path> dirs;
    for (const std::string &dir : options.dirs) {
        if (!std::filesystem::exists(dir))
            throw CliError(exit_usage, "--modules " + dir + ": no such file or directory");
        dirs.emplace_back(dir);
    }
    if (!options.only_given_dirs)
        for (const auto &dir : ubii::module_search_path())
            dirs.push_back(dir);
    for (const auto &dir : dirs) {
        loaded.searched.push_back(dir.string());
        for (auto &report : ubii::load_plugins(loaded.registry, dir))
            add_report(loaded, std::move(report));
    }
    if (!names.empty()) {
        for (const std::string &name : names)
            if (!loaded.registry.contains(name))
                throw CliError(
                    exit_modules,
                    "no processing module named " + name + " (found: " +
                        (loaded.registry.empty() ? "none" : joined(loaded.registry.names())) + ")");
        loaded.registry.retain(names);
    }
    for (auto &[name, arguments] : parse_arguments(options.arguments)) {
        try {
            loaded.registry.configure(name, std::move(arguments));
        } catch (const ubii::Error &error) {
            throw CliError(exit_usage, "--module-arg for " + name + ": " + error.what());
        } catch (const std::exception &error) {
            throw CliError(exit_usage,
                           "--module-arg for " + name + ": its factory refused: " + error.what());
        }
    }
    return loaded;
}

} // namespace ubii::cli
