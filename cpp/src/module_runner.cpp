#include "module_runner.hpp"

#include <algorithm>
#include <cmath>

#include "exception_text.hpp"

namespace ubii::detail
{

struct ModuleRunner::Worker {
    std::mutex mutex;
    std::condition_variable changed;
    std::optional<Pass> job;
    std::optional<Finished> done;
    std::atomic<bool> finished{false};
    bool quit = false;
    std::thread thread;
};

ModuleRunner::ModuleRunner(std::unique_ptr<ProcessingModule> module, std::string id,
                           Context context)
    : module_(std::move(module)), context_(context)
{
    module_->id_ = std::move(id);
    for (const ModuleIO &io : module_->description().inputs)
        slots_.push_back(Slot{&io, nullptr, false, {}});
    module_->lifecycle().set_error_handler(
        [this](std::exception_ptr error, const Transition<ProcessingStatus> &transition) {
            report(Status::callback_threw,
                   who() + ": a hook on " + std::string(to_string(transition.from())) + " -> " +
                       std::string(to_string(transition.to())) + " threw: " + what_of(error));
        });
}

ModuleRunner::~ModuleRunner()
{
    destroy();
}

std::string ModuleRunner::who() const
{
    return "processing module \"" + module_->name() + "\" (" + module_->id() + ")";
}

void ModuleRunner::report(Status status, const std::string &detail) noexcept
{
    if (!context_.error)
        return;
    try {
        context_.error(status, detail);
    } catch (...) { // the application's handler threw: there is nowhere left to report it to
    }
}

void ModuleRunner::create()
{
    module_->on_created();
    module_->lifecycle().transition(ProcessingStatus::created);
    if (module_->description().executor == Executor::worker) {
        worker_ = std::make_unique<Worker>();
        worker_->thread = std::thread([this, worker = worker_.get()] {
            std::unique_lock<std::mutex> lock(worker->mutex);
            for (;;) {
                worker->changed.wait(lock, [worker] { return worker->job || worker->quit; });
                if (!worker->job)
                    return;
                Pass pass = std::move(*worker->job);
                worker->job.reset();
                lock.unlock();
                Finished finished = execute(pass);
                lock.lock();
                worker->done = std::move(finished);
                worker->finished.store(true);
                worker->changed.notify_all();
                if (context_.wake) {
                    lock.unlock();
                    context_.wake();
                    lock.lock();
                }
            }
        });
    }
}

void ModuleRunner::start()
{
    module_->lifecycle().transition(ProcessingStatus::processing);
    start_ = context_.clock.now();
    next_tick_ = 0;
    if (const auto *frequency = std::get_if<Frequency>(&module_->description().mode))
        period_ns_ = 1e9 / frequency->hertz;
    last_pass_start_.reset();
}

void ModuleRunner::halt()
{
    if (module_->status() != ProcessingStatus::processing)
        throw StateError(who() + " is " + std::string(to_string(module_->status())) +
                         ", not processing");
    if (in_flight_) {
        {
            std::unique_lock<std::mutex> lock(worker_->mutex);
            worker_->changed.wait(lock, [this] { return worker_->finished.load(); });
        }
        collect(); // may halt the module itself (halt_after_errors)
        if (module_->status() != ProcessingStatus::processing)
            return;
    }
    module_->lifecycle().transition(ProcessingStatus::halted);
    try {
        module_->on_halted();
    } catch (...) {
        report(Status::callback_threw,
               who() + ": on_halted threw: " + what_of(std::current_exception()));
    }
}

void ModuleRunner::destroy() noexcept
{
    if (module_->status() == ProcessingStatus::destroyed)
        return;
    try {
        if (module_->status() == ProcessingStatus::processing)
            halt();
    } catch (...) {
        report(Status::callback_threw,
               who() + ": halting it threw: " + what_of(std::current_exception()));
    }
    if (worker_) {
        {
            std::lock_guard<std::mutex> lock(worker_->mutex);
            worker_->quit = true;
        }
        worker_->changed.notify_all();
        worker_->thread.join();
        worker_.reset();
        in_flight_ = false;
    }
    try {
        if (module_->status() != ProcessingStatus::initialized)
            module_->on_destroyed();
    } catch (...) {
        report(Status::callback_threw,
               who() + ": on_destroyed threw: " + what_of(std::current_exception()));
    }
    try {
        module_->lifecycle().transition(ProcessingStatus::destroyed);
    } catch (...) {
        report(Status::state, who() + ": " + what_of(std::current_exception()));
    }
}

ModuleRunner::Slot &ModuleRunner::slot(std::string_view input)
{
    for (Slot &candidate : slots_) {
        if (candidate.io->name == input)
            return candidate;
    }
    throw NotFound(who() + " has no input \"" + std::string(input) + "\"");
}

bool ModuleRunner::accepts(const Slot &slot, const Record &record)
{
    const RecordType wanted = slot.io->type();
    if (wanted == RecordType::NONE || record.type() == wanted)
        return true;
    ++type_mismatches_;
    report(Status::wrong_type,
           who() + ": input \"" + slot.io->name + "\" takes " +
               std::string(message_format(wanted)) + ", the record on \"" +
               std::string(record.topic()) + "\" holds " +
               (record.type() == RecordType::NONE ? std::string("nothing")
                                                  : std::string(message_format(record.type()))));
    return false;
}

void ModuleRunner::feed(std::string_view input, std::shared_ptr<const Record> record)
{
    Slot &target = slot(input);
    if (!record || !accepts(target, *record))
        return;
    if (target.fresh)
        ++inputs_dropped_;
    target.latest = std::move(record);
    target.fresh = true;
}

void ModuleRunner::feed_muxed(std::string_view input, std::string identity,
                              std::shared_ptr<const Record> record)
{
    Slot &target = slot(input);
    if (!record || !accepts(target, *record))
        return;
    const std::string_view topic = record->topic();
    auto entry =
        std::find_if(target.muxed.begin(), target.muxed.end(),
                     [topic](const MuxEntry &candidate) { return candidate.topic == topic; });
    if (entry == target.muxed.end()) {
        target.muxed.push_back(MuxEntry{std::string(topic), MuxedRecord{}});
        entry = std::prev(target.muxed.end());
    } else if (entry->fresh) {
        ++inputs_dropped_;
    }
    entry->record.identity = std::move(identity);
    target.latest = record;
    entry->record.record = std::move(record);
    entry->fresh = true;
}

bool ModuleRunner::triggered() const noexcept
{
    if (slots_.empty())
        return false;
    const auto updated = [](const Slot &slot) {
        return slot.fresh || std::any_of(slot.muxed.begin(), slot.muxed.end(),
                                         [](const MuxEntry &entry) { return entry.fresh; });
    };
    const auto &trigger = std::get<TriggerOnInput>(module_->description().mode);
    return trigger.all_inputs_need_update ? std::all_of(slots_.begin(), slots_.end(), updated)
                                          : std::any_of(slots_.begin(), slots_.end(), updated);
}

Clock::time_point ModuleRunner::deadline(std::uint64_t tick) const noexcept
{
    return start_ + std::chrono::nanoseconds(std::llround(static_cast<double>(tick) * period_ns_));
}

std::optional<Clock::time_point> ModuleRunner::next_due_at(Clock::time_point now) const
{
    if (in_flight_)
        return worker_->finished.load() ? std::optional(now) : std::nullopt;
    if (module_->status() != ProcessingStatus::processing)
        return std::nullopt;
    const ProcessingMode &mode = module_->description().mode;
    if (std::holds_alternative<Frequency>(mode))
        return deadline(next_tick_);
    if (const auto *trigger = std::get_if<TriggerOnInput>(&mode)) {
        if (!triggered())
            return std::nullopt;
        if (!last_pass_start_)
            return now;
        return std::max(now, *last_pass_start_ + trigger->min_delay);
    }
    if (std::holds_alternative<Free>(mode))
        return now;
    return std::nullopt;
}

Pass ModuleRunner::begin_pass(Clock::time_point now, std::optional<std::chrono::nanoseconds> delta)
{
    std::chrono::nanoseconds since_last{0};
    if (last_pass_start_) {
        since_last = now - *last_pass_start_;
        intervals_.add(since_last);
    }
    last_pass_start_ = now;
    if (std::holds_alternative<Frequency>(module_->description().mode)) {
        // The tick whose deadline is the latest one passed; the ones between it and next_tick_
        // were missed while this pass was late.
        const double elapsed = static_cast<double>((now - start_).count());
        std::uint64_t tick =
            std::max<std::uint64_t>(next_tick_, static_cast<std::uint64_t>(elapsed / period_ns_));
        while (deadline(tick + 1) <= now)
            ++tick;
        while (tick > next_tick_ && deadline(tick) > now)
            --tick;
        skipped_ticks_ += tick - next_tick_;
        next_tick_ = tick + 1;
    }
    std::vector<Pass::Input> inputs;
    inputs.reserve(slots_.size());
    for (Slot &slot : slots_) {
        Pass::Input input{slot.io, slot.latest, {}, slot.fresh};
        for (MuxEntry &entry : slot.muxed) {
            input.muxed.push_back(entry.record);
            input.updated = input.updated || entry.fresh;
            entry.fresh = false;
        }
        slot.fresh = false;
        inputs.push_back(std::move(input));
    }
    ++passes_;
    return Pass(std::move(inputs), module_->description().outputs, delta.value_or(since_last),
                passes_);
}

ModuleRunner::Finished ModuleRunner::execute(Pass &pass) noexcept
{
    Finished finished;
    const Clock::time_point began = context_.clock.now();
    try {
        module_->on_processing(pass);
        finished.outputs = pass.take_outputs();
    } catch (...) {
        finished.error = std::current_exception();
    }
    finished.execution = context_.clock.now() - began;
    finished.log = pass.take_log();
    return finished;
}

void ModuleRunner::hand_on_log(const std::vector<std::string> &lines) noexcept
{
    if (!context_.log)
        return;
    for (const std::string &line : lines) {
        try {
            context_.log(*module_, line);
        } catch (...) {
            report(Status::callback_threw,
                   who() + ": the log handler threw: " + what_of(std::current_exception()));
        }
    }
}

void ModuleRunner::finish(Finished finished)
{
    executions_.add(finished.execution);
    hand_on_log(finished.log);
    if (finished.error) {
        ++errors_;
        ++errors_in_a_row_;
        report(Status::callback_threw, who() + ": on_processing threw: " + what_of(finished.error));
        const unsigned limit = module_->description().halt_after_errors;
        if (limit > 0 && errors_in_a_row_ >= limit &&
            module_->status() == ProcessingStatus::processing) {
            report(Status::callback_threw, who() + ": halted after " +
                                               std::to_string(errors_in_a_row_) +
                                               " passes in a row threw");
            halt();
        }
        return;
    }
    errors_in_a_row_ = 0;
    for (const PassOutput &output : finished.outputs) {
        Status status = Status::unsupported;
        std::string why = "nothing publishes outputs (Scheduler::on_output)";
        if (context_.output) {
            try {
                status = context_.output(*module_, output);
                why = describe(status);
            } catch (const Error &error) { // the sink's own account of why, e.g. a wiring's
                status = error.status();
                why = error.what();
            } catch (...) {
                status = Status::callback_threw;
                why = "the output sink threw: " + what_of(std::current_exception());
            }
        }
        if (status != Status::ok) {
            ++outputs_failed_;
            report(status, who() + ": output \"" + output.name + "\" not published: " + why);
        }
    }
}

void ModuleRunner::collect()
{
    Finished finished;
    {
        std::lock_guard<std::mutex> lock(worker_->mutex);
        finished = std::move(*worker_->done);
        worker_->done.reset();
        worker_->finished.store(false);
    }
    in_flight_ = false;
    finish(std::move(finished));
}

void ModuleRunner::run_due()
{
    if (in_flight_) {
        if (!worker_->finished.load())
            return;
        collect();
    }
    if (module_->status() != ProcessingStatus::processing)
        return;
    const Clock::time_point now = context_.clock.now();
    const std::optional<Clock::time_point> due = next_due_at(now);
    if (!due || *due > now)
        return;
    Pass pass = begin_pass(now, std::nullopt);
    if (worker_) {
        {
            std::lock_guard<std::mutex> lock(worker_->mutex);
            worker_->job.emplace(std::move(pass));
        }
        in_flight_ = true;
        worker_->changed.notify_all();
    } else {
        finish(execute(pass));
    }
}

std::vector<PassOutput> ModuleRunner::step(const std::vector<Record> &inputs,
                                           std::chrono::nanoseconds delta)
{
    if (!std::holds_alternative<Lockstep>(module_->description().mode))
        throw StateError(who() + " runs in " + std::string(mode_name(module_->description().mode)) +
                         " mode, not lockstep");
    if (module_->status() != ProcessingStatus::processing)
        throw StateError(who() + " is " + std::string(to_string(module_->status())) +
                         ", not processing");
    for (const Record &record : inputs)
        feed(record.topic(), std::make_shared<const Record>(record));
    Pass pass = begin_pass(context_.clock.now(), delta);
    Finished finished = execute(pass);
    executions_.add(finished.execution);
    hand_on_log(finished.log);
    if (finished.error) {
        ++errors_;
        std::rethrow_exception(finished.error);
    }
    return std::move(finished.outputs);
}

Timing ModuleRunner::timing() const
{
    Timing timing;
    timing.intervals = intervals_.stats();
    timing.execution = executions_.stats();
    std::optional<Seconds> period;
    const ProcessingMode &mode = module_->description().mode;
    if (const auto *frequency = std::get_if<Frequency>(&mode))
        period = Seconds(1.0 / frequency->hertz);
    else if (const auto *trigger = std::get_if<TriggerOnInput>(&mode);
             trigger != nullptr && trigger->min_delay.count() > 0)
        period = std::chrono::duration_cast<Seconds>(trigger->min_delay);
    if (period) {
        if (timing.intervals.count > 0)
            timing.interval_performance = performance(timing.intervals.mean, *period);
        if (timing.execution.count > 0)
            timing.execution_performance = performance(timing.execution.mean, *period);
    }
    timing.passes = passes_;
    timing.skipped_ticks = skipped_ticks_;
    timing.inputs_dropped = inputs_dropped_;
    timing.type_mismatches = type_mismatches_;
    timing.errors = errors_;
    timing.outputs_failed = outputs_failed_;
    return timing;
}

} // namespace ubii::detail
