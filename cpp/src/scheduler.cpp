#include "ubii/scheduler.hpp"

#include <algorithm>
#include <map>

#include "module_runner.hpp"

namespace ubii
{

struct Scheduler::Impl {
    explicit Impl(Clock &scheduler_clock) : clock(scheduler_clock)
    {
    }
    detail::ModuleRunner &find(std::string_view id) const
    {
        const auto found = runners.find(id);
        if (found == runners.end())
            throw NotFound("no processing module \"" + std::string(id) + "\" in the scheduler");
        return *found->second;
    }

    Clock &clock;
    OutputSink output;
    ErrorHandler error;
    LogHandler log;
    std::function<void()> wake;
    // Ordered by id, so that modules due at once run in a stable order.
    std::map<std::string, std::unique_ptr<detail::ModuleRunner>, std::less<>> runners;
    std::uint64_t next_number = 1;
};

Scheduler::Scheduler(Clock &clock) : impl_(std::make_unique<Impl>(clock))
{
}

Scheduler::~Scheduler()
{
    // Destroyed one by one (each joins its worker) before the handlers they report to go.
    while (!impl_->runners.empty())
        impl_->runners.erase(impl_->runners.begin());
}

Clock &Scheduler::clock() const noexcept
{
    return impl_->clock;
}

void Scheduler::on_output(OutputSink sink)
{
    impl_->output = std::move(sink);
}

void Scheduler::on_error(ErrorHandler handler)
{
    impl_->error = std::move(handler);
}

void Scheduler::on_log(LogHandler handler)
{
    impl_->log = std::move(handler);
}

void Scheduler::set_waker(std::function<void()> wake)
{
    if (std::any_of(impl_->runners.begin(), impl_->runners.end(),
                    [](const auto &entry) { return entry.second->worker_busy(); }))
        throw StateError("Scheduler::set_waker while a worker pass runs");
    impl_->wake = std::move(wake);
}

std::string Scheduler::add(std::unique_ptr<ProcessingModule> module)
{
    if (!module)
        throw InvalidArgument("Scheduler::add without a module");
    std::string id = module->id();
    if (id.empty()) {
        do
            id = module->name() + "#" + std::to_string(impl_->next_number++);
        while (impl_->runners.count(id) > 0);
    } else if (impl_->runners.count(id) > 0) {
        throw InvalidArgument("a processing module with id \"" + id + "\" runs already");
    }
    auto runner = std::make_unique<detail::ModuleRunner>(
        std::move(module), id,
        detail::ModuleRunner::Context{impl_->clock, impl_->output, impl_->error, impl_->log,
                                      impl_->wake});
    runner->create();
    impl_->runners.emplace(id, std::move(runner));
    return id;
}

void Scheduler::start(std::string_view id)
{
    impl_->find(id).start();
}

void Scheduler::halt(std::string_view id)
{
    impl_->find(id).halt();
}

void Scheduler::remove(std::string_view id)
{
    const auto found = impl_->runners.find(id);
    if (found == impl_->runners.end())
        throw NotFound("no processing module \"" + std::string(id) + "\" in the scheduler");
    // Out of the map first: a handler the module reports to may look the scheduler up.
    std::unique_ptr<detail::ModuleRunner> runner = std::move(found->second);
    impl_->runners.erase(found);
    runner->destroy();
}

bool Scheduler::contains(std::string_view id) const noexcept
{
    return impl_->runners.find(id) != impl_->runners.end();
}

bool Scheduler::empty() const noexcept
{
    return impl_->runners.empty();
}

std::vector<std::string> Scheduler::ids() const
{
    std::vector<std::string> ids;
    for (const auto &entry : impl_->runners)
        ids.push_back(entry.first);
    return ids;
}

ProcessingModule &Scheduler::module(std::string_view id)
{
    return impl_->find(id).module();
}

Timing Scheduler::timing(std::string_view id) const
{
    return impl_->find(id).timing();
}

void Scheduler::feed(std::string_view id, std::string_view input,
                     std::shared_ptr<const Record> record)
{
    impl_->find(id).feed(input, std::move(record));
}

void Scheduler::feed_muxed(std::string_view id, std::string_view input, std::string identity,
                           std::shared_ptr<const Record> record)
{
    impl_->find(id).feed_muxed(input, std::move(identity), std::move(record));
}

std::optional<Clock::time_point> Scheduler::next_due() const
{
    if (impl_->runners.empty())
        return std::nullopt;
    const Clock::time_point now = impl_->clock.now();
    std::optional<Clock::time_point> earliest;
    for (const auto &entry : impl_->runners) {
        std::optional<Clock::time_point> due = entry.second->next_due_at(now);
        if (!due && entry.second->worker_busy() && !impl_->wake)
            due = now + std::chrono::milliseconds(1); // nothing will wake the caller: look again
        if (due && (!earliest || *due < *earliest))
            earliest = due;
    }
    return earliest;
}

void Scheduler::run_due()
{
    // A module may be removed by a handler a pass reports to: walk a snapshot of the ids.
    for (const std::string &id : ids()) {
        const auto found = impl_->runners.find(id);
        if (found != impl_->runners.end())
            found->second->run_due();
    }
}

std::vector<Record> Scheduler::step(std::string_view id, const std::vector<Record> &inputs,
                                    std::chrono::nanoseconds delta)
{
    std::vector<Record> outputs;
    for (PassOutput &output : impl_->find(id).step(inputs, delta))
        outputs.emplace_back(std::move(output.name), std::move(output.value));
    return outputs;
}

LockstepProcessingReply Scheduler::step(const LockstepProcessingRequest &request)
{
    std::vector<std::string> ids(request.processing_module_ids().begin(),
                                 request.processing_module_ids().end());
    if (ids.empty()) {
        for (const auto &entry : impl_->runners) {
            if (std::holds_alternative<Lockstep>(entry.second->module().description().mode))
                ids.push_back(entry.first);
        }
    }
    std::vector<Record> records;
    records.reserve(static_cast<std::size_t>(request.records_size()));
    for (const TopicDataRecord &message : request.records())
        records.push_back(record_from_message(message));
    const auto delta = std::chrono::milliseconds(request.delta_time_ms());

    LockstepProcessingReply reply;
    for (const std::string &id : ids) {
        const auto &inputs = impl_->find(id).module().description().inputs;
        std::vector<Record> mine;
        for (const Record &record : records) {
            if (find_io(inputs, record.topic()) != nullptr)
                mine.push_back(record);
        }
        for (const Record &output : step(id, mine, delta))
            *reply.add_records() = message_from_record(output);
        reply.add_processing_module_ids(id);
    }
    return reply;
}

namespace
{
template <class T>
T read_field(const google::protobuf::Message &message,
             const google::protobuf::FieldDescriptor *field)
{
    const auto *reflection = message.GetReflection();
    if constexpr (std::is_same_v<T, double>)
        return reflection->GetDouble(message, field);
    else if constexpr (std::is_same_v<T, float>)
        return reflection->GetFloat(message, field);
    else if constexpr (std::is_same_v<T, bool>)
        return reflection->GetBool(message, field);
    else if constexpr (std::is_same_v<T, std::int32_t>)
        return reflection->GetInt32(message, field);
    else if constexpr (std::is_same_v<T, std::string>)
        return reflection->GetString(message, field);
    else
        return static_cast<const T &>(reflection->GetMessage(message, field));
}
} // namespace

Record record_from_message(const TopicDataRecord &message)
{
    const auto *reflection = message.GetReflection();
    const auto *oneof = message.GetDescriptor()->FindOneofByName("type");
    const auto *field =
        oneof != nullptr ? reflection->GetOneofFieldDescriptor(message, oneof) : nullptr;
    Value value;
    if (field != nullptr) {
        switch (static_cast<RecordType>(field->number())) {
#define UBII_CPP_VALUE_FROM_FIELD(upper, number, name, format, cpp_type)                           \
    case RecordType::upper:                                                                        \
        value = Value(RecordType::upper, read_field<cpp_type>(message, field));                    \
        break;
            UBII_RECORD_MEMBER_LIST(UBII_CPP_VALUE_FROM_FIELD)
#undef UBII_CPP_VALUE_FROM_FIELD
        case RecordType::NONE:
            break;
        }
    }
    Record record(message.topic(), std::move(value));
    if (!message.client_id().empty())
        record.set_client_id(message.client_id());
    return record;
}

TopicDataRecord message_from_record(const Record &record)
{
    TopicDataRecord message;
    message.set_topic(std::string(record.topic()));
    if (!record.client_id().empty())
        message.set_client_id(std::string(record.client_id()));
    const auto *reflection = message.GetReflection();
    const auto *field = message.GetDescriptor()->FindFieldByNumber(static_cast<int>(record.type()));
    if (field == nullptr)
        return message;
    record.value().visit([&](const auto &held) {
        using T = std::decay_t<decltype(held)>;
        if constexpr (std::is_same_v<T, std::monostate>)
            return;
        else if constexpr (std::is_same_v<T, double>)
            reflection->SetDouble(&message, field, held);
        else if constexpr (std::is_same_v<T, float>)
            reflection->SetFloat(&message, field, held);
        else if constexpr (std::is_same_v<T, bool>)
            reflection->SetBool(&message, field, held);
        else if constexpr (std::is_same_v<T, std::int32_t>)
            reflection->SetInt32(&message, field, held);
        else if constexpr (std::is_same_v<T, std::string>)
            reflection->SetString(&message, field, held);
        else
            reflection->MutableMessage(&message, field)->CopyFrom(held);
    });
    return message;
}

} // namespace ubii
