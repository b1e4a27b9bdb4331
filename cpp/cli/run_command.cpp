// `ubii-node run [MODULE...]`: a dedicated processing node. Offers the modules found (or those
// named) to the master and runs what sessions assign to it until SIGINT/SIGTERM, then deregisters.
// With --wire it also runs modules of its own accord, wired to topics (for masters that assign no
// sessions, such as the npm master).
// One line per event on stdout; the timing of each running module on SIGUSR1 or every --stats S.
#include <ctime>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>

#include "cli_error.hpp"
#include "commands.hpp"
#include "message_output.hpp"
#include "module_loading.hpp"

namespace ubii::cli
{

namespace
{

struct RunOptions {
    std::vector<std::string> names;
    ModuleOptions modules;
    // MODULE:io=TOPIC
    std::vector<std::string> wires;
    double stats_s = 0;
};

bool declares(const google::protobuf::RepeatedPtrField<ubii::ModuleIOSpec> &ios,
              const std::string &name)
{
    for (const auto &io : ios)
        if (io.internal_name() == name)
            return true;
    return false;
}

// --wire MODULE:io=TOPIC, grouped by module; CliError(exit_usage) for a malformed one, an unknown
// module or a name the module does not declare.
std::map<std::string, ubii::Wiring> parse_wires(const std::vector<std::string> &wires,
                                                const ubii::ModuleRegistry &registry)
{
    std::map<std::string, ubii::Wiring> wiring;
    for (const std::string &text : wires) {
        const std::size_t colon = text.find(':');
        const std::size_t equals = text.find('=', colon == std::string::npos ? 0 : colon);
        if (colon == 0 || colon == std::string::npos || equals == std::string::npos ||
            equals == colon + 1 || equals + 1 == text.size())
            throw CliError(exit_usage, "--wire " + text + " is not MODULE:io=TOPIC");
        const std::string module = text.substr(0, colon);
        const std::string io = text.substr(colon + 1, equals - colon - 1);
        const std::string topic = text.substr(equals + 1);
        if (!registry.contains(module))
            throw CliError(exit_usage, "--wire " + text + ": no module named " + module);
        const ubii::ProcessingModuleSpec &spec = registry.spec(module);
        if (declares(spec.inputs(), io))
            wiring[module].input(io, topic);
        else if (declares(spec.outputs(), io))
            wiring[module].output(io, topic);
        else
            throw CliError(exit_usage, "--wire " + text + ": " + module +
                                           " has no input or output named " + io);
    }
    return wiring;
}

std::string clock_time()
{
    const auto now = std::chrono::system_clock::now();
    const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
    const auto millis =
        std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() %
        1000;
    std::tm local{};
    localtime_r(&seconds, &local);
    std::ostringstream text;
    text << std::put_time(&local, "%H:%M:%S") << '.' << std::setw(3) << std::setfill('0') << millis;
    return text.str();
}

void log_line(const std::string &text)
{
    std::cout << clock_time() << ' ' << text << std::endl;
}

std::string event_line(const ubii::SessionEvent &event)
{
    std::string line = std::string(ubii::to_string(event.kind)) + ' ' + event.module_name;
    if (!event.module_id.empty())
        line += " module=" + event.module_id;
    if (!event.session_id.empty())
        line += " session=" + event.session_id;
    if (!event.detail.empty())
        line += ": " + event.detail;
    return line;
}

std::string milliseconds(ubii::Seconds seconds)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(2) << seconds.count() * 1000 << " ms";
    return text.str();
}

std::string performance_text(const std::optional<double> &performance)
{
    if (!performance)
        return "-";
    std::ostringstream text;
    text << std::fixed << std::setprecision(2) << *performance;
    return text.str();
}

void report_timing(ubii::Node &node)
{
    // Session modules and --wire modules alike: every module the node's scheduler runs.
    const std::vector<std::string> ids = node.scheduler().ids();
    if (ids.empty())
        log_line("timing: no module running");
    for (const std::string &id : ids) {
        const ubii::Timing timing = node.scheduler().timing(id);
        log_line("timing " + node.scheduler().module(id).name() + " module=" + id +
                 ": passes=" + std::to_string(timing.passes) +
                 " interval=" + milliseconds(timing.intervals.mean) + " (perf " +
                 performance_text(timing.interval_performance) + ")" +
                 " execution=" + milliseconds(timing.execution.mean) + " (perf " +
                 performance_text(timing.execution_performance) + ")" +
                 " dropped=" + std::to_string(timing.inputs_dropped) + " skipped=" +
                 std::to_string(timing.skipped_ticks) + " errors=" + std::to_string(timing.errors));
    }
}

int serve(Context &context, const RunOptions &options)
{
    if (options.stats_s < 0)
        throw CliError(exit_usage, "--stats must not be negative");
    LoadedModules loaded = load_modules(options.modules, options.names);
    if (loaded.registry.empty())
        throw CliError(exit_modules,
                       "no processing modules to offer (looked in: " + loaded.searched_text() +
                           "; give --modules DIR or set UBII_MODULE_PATH)");
    ubii::NodeOptions node_options = context.connection.node_options();
    node_options.is_dedicated_processing_node = true;
    node_options.reconnect.max_attempts = 0; // a serving node waits for its master to come back
    ubii::Node node(node_options);
    const std::vector<std::string> names = loaded.registry.names();
    std::vector<ubii::RunningModule> wired;
    for (const auto &[module, wiring] : parse_wires(options.wires, loaded.registry)) {
        try {
            wired.push_back(node.run(loaded.registry.create(module), wiring));
        } catch (const std::exception &error) {
            throw CliError(exit_modules, module + " could not start: " + error.what());
        }
        log_line("running " + module + " as " + wired.back().id() + ", wired by --wire");
    }
    node.serve_sessions(std::move(loaded.registry));
    node.on_session_event([](const ubii::SessionEvent &event) { log_line(event_line(event)); });
    node.on_state([&node](ubii::ConnectionState, ubii::ConnectionState current, ubii::Status) {
        if (current == ubii::ConnectionState::ready)
            log_line("connected as client " + node.client_id());
        else if (current == ubii::ConnectionState::reconnecting)
            log_line("lost the master; reconnecting");
    });
    // What the modules' libraries say (Tesseract's warnings, through Pass::log).
    node.scheduler().on_log([](const ubii::ProcessingModule &module, std::string_view line) {
        log_line(module.id() + ": " + std::string(line));
    });
    const int verbosity = context.verbosity;
    node.on_error([verbosity](ubii::Status status, std::string_view detail) {
        if (verbosity > 0)
            log_line("error: " + std::string(ubii::describe(status)) + ": " + std::string(detail));
    });
    connect(node, context.connection.connect_timeout());
    log_line("offering " + joined(names));
    const auto period = std::chrono::milliseconds(static_cast<long long>(options.stats_s * 1000));
    auto next_stats = std::chrono::steady_clock::now() + period;
    while (!interrupted()) {
        node.poll(std::chrono::milliseconds(200));
        const bool periodic = period.count() > 0 && std::chrono::steady_clock::now() >= next_stats;
        if (periodic)
            next_stats += period;
        if (take_report_request() || periodic)
            report_timing(node);
    }
    log_line("stopping");
    const bool deregistered = node.stop_wait();
    log_line(deregistered ? "stopped" : "stopped without the master confirming deregistration");
    return exit_ok;
}

} // namespace

void add_run_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand(
        "run", "Serve sessions as a dedicated processing node with the modules found (or the "
               "MODULEs named) until interrupted");
    auto options = std::make_shared<RunOptions>();
    command->add_option("MODULE", options->names, "offer only these modules");
    add_module_options(*command, options->modules);
    command
        ->add_option("--wire", options->wires,
                     "MODULE:io=TOPIC: run MODULE here, its input or output io on TOPIC, without a "
                     "session (masters that assign none); repeatable, one module instance each")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    command->add_option("--stats", options->stats_s,
                        "print each running module's timing every S seconds (also on SIGUSR1)");
    command->callback([&context, options] {
        context.action = [&context, options] { return serve(context, *options); };
    });
}

} // namespace ubii::cli
