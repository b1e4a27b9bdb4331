#include "ubii/processing_module.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ubii
{

namespace
{

std::vector<std::pair<ProcessingStatus, ProcessingStatus>> lifecycle_transitions()
{
    using S = ProcessingStatus;
    return {{S::initialized, S::created},  {S::created, S::processing}, {S::processing, S::halted},
            {S::halted, S::processing},    {S::created, S::destroyed},  {S::halted, S::destroyed},
            {S::initialized, S::destroyed}};
}

void describe_io(const ModuleIO &io, ModuleIOSpec &spec)
{
    spec.set_internal_name(io.name);
    spec.set_message_format(io.message_format);
}

void check_io_names(const std::vector<ModuleIO> &ios, const char *kind, const std::string &module)
{
    for (std::size_t i = 0; i < ios.size(); ++i) {
        if (ios[i].name.empty())
            throw InvalidArgument("processing module \"" + module + "\": an " + kind +
                                  " without a name");
        for (std::size_t j = 0; j < i; ++j) {
            if (ios[j].name == ios[i].name)
                throw InvalidArgument("processing module \"" + module + "\": two " + kind +
                                      "s named \"" + ios[i].name + "\"");
        }
        if (!ios[i].message_format.empty() && ios[i].type() == RecordType::NONE)
            throw InvalidArgument("processing module \"" + module + "\": " + kind + " \"" +
                                  ios[i].name + "\" has the message format \"" +
                                  ios[i].message_format + "\", which no record member holds");
    }
}

void check_mode(const ProcessingMode &mode, const std::string &module)
{
    if (const auto *frequency = std::get_if<Frequency>(&mode)) {
        if (!(frequency->hertz > 0) || !std::isfinite(frequency->hertz) || frequency->hertz > 1e6)
            throw InvalidArgument("processing module \"" + module +
                                  "\": a frequency must be above 0 Hz and at most 1 MHz, not " +
                                  std::to_string(frequency->hertz));
    } else if (const auto *trigger = std::get_if<TriggerOnInput>(&mode)) {
        if (trigger->min_delay.count() < 0)
            throw InvalidArgument("processing module \"" + module + "\": a negative min_delay");
    }
}

} // namespace

std::string_view to_string(ProcessingStatus status) noexcept
{
    switch (status) {
    case ProcessingStatus::initialized:
        return "initialized";
    case ProcessingStatus::created:
        return "created";
    case ProcessingStatus::processing:
        return "processing";
    case ProcessingStatus::halted:
        return "halted";
    case ProcessingStatus::destroyed:
        return "destroyed";
    }
    return "unknown";
}

std::string_view mode_name(const ProcessingMode &mode) noexcept
{
    static constexpr std::string_view names[] = {"frequency", "trigger_on_input", "lockstep",
                                                 "free"};
    return names[mode.index()];
}

Pass::Pass(std::vector<Input> inputs, const std::vector<ModuleIO> &outputs,
           std::chrono::nanoseconds delta, std::uint64_t number)
    : inputs_(std::move(inputs)), declared_outputs_(&outputs), delta_(delta), number_(number)
{
}

void Pass::log(std::string line)
{
    log_.push_back(std::move(line));
}

const Pass::Input &Pass::find(std::string_view input) const
{
    for (const Input &candidate : inputs_) {
        if (candidate.io->name == input)
            return candidate;
    }
    throw NotFound("the module has no input \"" + std::string(input) + "\"");
}

const Record *Pass::record(std::string_view input) const
{
    return find(input).latest.get();
}

void Pass::throw_no_record(std::string_view input)
{
    throw NotFound("no record has arrived on input \"" + std::string(input) + "\" yet");
}

bool Pass::updated(std::string_view input) const
{
    return find(input).updated;
}

const std::vector<MuxedRecord> &Pass::muxed(std::string_view input) const
{
    return find(input).muxed;
}

const ModuleIO *find_io(const std::vector<ModuleIO> &ios, std::string_view name) noexcept
{
    const auto found = std::find_if(ios.begin(), ios.end(),
                                    [name](const ModuleIO &io) { return io.name == name; });
    return found != ios.end() ? &*found : nullptr;
}

void Pass::check_output(std::string_view output, const Value &value) const
{
    const ModuleIO *declared = find_io(*declared_outputs_, output);
    if (declared == nullptr)
        throw NotFound("the module has no output \"" + std::string(output) + "\"");
    if (value.empty())
        throw WrongType("output \"" + std::string(output) + "\" cannot take an empty value");
    const RecordType wanted = declared->type();
    if (wanted != RecordType::NONE && value.type() != wanted)
        throw WrongType("output \"" + std::string(output) + "\" takes " +
                        std::string(message_format(wanted)) + ", not " +
                        std::string(message_format(value.type())));
}

void Pass::set_output(std::string_view output, Value value)
{
    check_output(output, value);
    for (auto &set : outputs_) {
        if (set.name == output) {
            if (set.demuxed)
                throw StateError("output \"" + std::string(output) +
                                 "\" holds demultiplexed elements already");
            set.value = std::move(value);
            return;
        }
    }
    outputs_.push_back(PassOutput{std::string(output), std::move(value), false, {}});
}

void Pass::add_demuxed_output(std::string_view output, Value value,
                              std::vector<std::string> topic_params)
{
    check_output(output, value);
    for (const auto &set : outputs_) {
        if (set.name == output && !set.demuxed)
            throw StateError("output \"" + std::string(output) + "\" was set as a single value");
    }
    outputs_.push_back(
        PassOutput{std::string(output), std::move(value), true, std::move(topic_params)});
}

ProcessingModule::ProcessingModule(ModuleDescription description)
    : description_(std::move(description)),
      lifecycle_("processing module", ProcessingStatus::initialized, lifecycle_transitions(),
                 [](ProcessingStatus status) { return to_string(status); })
{
    if (description_.name.empty())
        throw InvalidArgument("a processing module needs a name");
    check_io_names(description_.inputs, "input", description_.name);
    check_io_names(description_.outputs, "output", description_.name);
    check_mode(description_.mode, description_.name);
}

ProcessingModule::~ProcessingModule() = default;

ProcessingModuleSpec ProcessingModule::spec() const
{
    ProcessingModuleSpec spec;
    spec.set_id(id_);
    spec.set_name(description_.name);
    spec.set_session_id(session_id_);
    spec.set_node_id(node_id_);
    spec.set_description(description_.description);
    for (const auto &author : description_.authors)
        spec.add_authors(author);
    for (const auto &tag : description_.tags)
        spec.add_tags(tag);
    spec.set_status(static_cast<ProcessingModuleSpec::Status>(status()));
    spec.set_language(ProcessingModuleSpec::CPP);
    for (const auto &io : description_.inputs)
        describe_io(io, *spec.add_inputs());
    for (const auto &io : description_.outputs)
        describe_io(io, *spec.add_outputs());
    auto &mode = *spec.mutable_processing_mode();
    std::visit(
        [&mode](const auto &chosen) {
            using M = std::decay_t<decltype(chosen)>;
            if constexpr (std::is_same_v<M, Frequency>) {
                const double rounded = std::round(chosen.hertz);
                mode.mutable_frequency()->set_hertz(static_cast<std::int32_t>(std::clamp(
                    rounded, 1.0, static_cast<double>(std::numeric_limits<std::int32_t>::max()))));
            } else if constexpr (std::is_same_v<M, TriggerOnInput>) {
                auto &trigger = *mode.mutable_trigger_on_input();
                trigger.set_min_delay_ms(static_cast<std::int32_t>(std::min<long long>(
                    chosen.min_delay.count(), std::numeric_limits<std::int32_t>::max())));
                trigger.set_all_inputs_need_update(chosen.all_inputs_need_update);
            } else if constexpr (std::is_same_v<M, Lockstep>) {
                mode.mutable_lockstep();
            } else {
                mode.mutable_free();
            }
        },
        description_.mode);
    return spec;
}

namespace
{
class FunctionModule final : public ProcessingModule
{
  public:
    FunctionModule(ModuleDescription description, std::function<void(Pass &)> fn)
        : ProcessingModule(std::move(description)), fn_(std::move(fn))
    {
        if (!fn_)
            throw InvalidArgument("processing module \"" + name() + "\" without a function");
    }

  protected:
    void on_processing(Pass &pass) override
    {
        fn_(pass);
    }

  private:
    std::function<void(Pass &)> fn_;
};
} // namespace

std::unique_ptr<ProcessingModule> make_module(ModuleDescription description,
                                              std::function<void(Pass &)> on_processing)
{
    return std::make_unique<FunctionModule>(std::move(description), std::move(on_processing));
}

} // namespace ubii
