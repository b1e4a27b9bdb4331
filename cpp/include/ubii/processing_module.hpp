#ifndef UBII_PROCESSING_MODULE_HPP
#define UBII_PROCESSING_MODULE_HPP

// ubii::ProcessingModule: a computation with named, typed inputs and outputs that a scheduler runs
// in one of four processing modes (thesis §2.3.3; Ubi-Interact's ubii.processing.ProcessingModule).
//
//     class Sum : public ubii::ProcessingModule {
//       public:
//         Sum() : ProcessingModule({"sum", "adds a and b",
//                                   {ubii::input<double>("a"), ubii::input<double>("b")},
//                                   {ubii::output<double>("sum")},
//                                   ubii::TriggerOnInput{}}) {}
//         void on_processing(ubii::Pass &pass) override {
//             pass.set_output("sum", pass.input<double>("a") + pass.input<double>("b"));
//         }
//     };
//
// A pass reads its inputs and sets its outputs through the Pass it is given: on the worker
// executor that is the only state shared with the node, so on_processing touches nothing else of
// the node. The lifecycle hooks on_created, on_halted and on_destroyed always run on the thread
// that polls the node, never during a pass.

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "ubii/error.hpp"
#include "ubii/messages.hpp"
#include "ubii/protocol.hpp"
#include "ubii/record.hpp"
#include "ubii/record_type.hpp"
#include "ubii/value.hpp"

namespace ubii
{

namespace detail
{
class ModuleRunner;
class SessionHost;
} // namespace detail

// The module's status, as ubii.processing.ProcessingModule.Status.
enum class ProcessingStatus { initialized, created, processing, halted, destroyed };
std::string_view to_string(ProcessingStatus status) noexcept;
using ProcessingProtocol = Protocol<ProcessingStatus>;

// One input or output: its name inside the module, and the message format of its records as
// specs name it ("double", "ubii.dataStructure.Vector3"); "" takes any record.
struct ModuleIO {
    std::string name;
    std::string message_format;
    // The record member of message_format; NONE when it names none (any record is taken).
    RecordType type() const noexcept
    {
        return record_type_for_format(message_format);
    }
};
// The input or output named `name` among `ios`; nullptr if there is none.
const ModuleIO *find_io(const std::vector<ModuleIO> &ios, std::string_view name) noexcept;

template <class T> ModuleIO input(std::string name)
{
    static_assert(is_record_value_v<T>, "no TopicDataRecord member holds this type");
    return ModuleIO{std::move(name), std::string(message_format(record_type_of<T>))};
}
template <class T> ModuleIO output(std::string name)
{
    return input<T>(std::move(name));
}

// The processing modes (ubii.processing.ProcessingMode).
// Passes at start + k/hertz, without drift: a late pass runs once, the deadlines it missed are
// counted (Timing::skipped_ticks), never queued.
struct Frequency {
    double hertz = 30;
};
// A pass when inputs arrive (all of the module's inputs, with all_inputs_need_update), at least
// min_delay after the previous pass began: an input inside the delay defers the pass to its end.
struct TriggerOnInput {
    std::chrono::milliseconds min_delay{0};
    bool all_inputs_need_update = false;
};
// Passes only when a driver steps the module (ubii::LockstepDriver, Scheduler::step).
struct Lockstep {
};
// A pass every time the node's loop turns, with the node's I/O done between passes.
struct Free {
};
using ProcessingMode = std::variant<Frequency, TriggerOnInput, Lockstep, Free>;
std::string_view mode_name(const ProcessingMode &mode) noexcept;

// Where passes run: in the thread polling the node, or on a worker thread of the module's own,
// for passes long enough to stall the node's I/O (OCR: 100-1000 ms).
enum class Executor { loop, worker };

struct ModuleDescription {
    ModuleDescription() = default;
    ModuleDescription(std::string module_name, std::string module_description,
                      std::vector<ModuleIO> module_inputs, std::vector<ModuleIO> module_outputs,
                      ProcessingMode processing_mode = Frequency{},
                      Executor pass_executor = Executor::loop)
        : name(std::move(module_name)), description(std::move(module_description)),
          inputs(std::move(module_inputs)), outputs(std::move(module_outputs)),
          mode(processing_mode), executor(pass_executor)
    {
    }

    std::string name;
    std::string description;
    std::vector<ModuleIO> inputs;
    std::vector<ModuleIO> outputs;
    ProcessingMode mode = Frequency{};
    Executor executor = Executor::loop;
    std::vector<std::string> tags;
    std::vector<std::string> authors;
    // Halts the module after this many passes in a row threw; 0: never.
    unsigned halt_after_errors = 0;
};

// A module's latest record of one topic a mux input matches, with the identity taken from the
// topic (TopicMux.identity_match_pattern; the whole topic without one).
struct MuxedRecord {
    std::string identity;
    std::shared_ptr<const Record> record;
};

// A value a pass set on an output. A demultiplexed element's `topic_params` fill the `{{#0}}`,
// `{{#1}}`, ... of the topic format its output is wired to (TopicDemux.output_topic_format).
struct PassOutput {
    std::string name;
    Value value;
    bool demuxed = false;
    std::vector<std::string> topic_params;
};

// One pass of a module: its inputs as they were when the pass began, and the outputs it sets.
class Pass
{
  public:
    struct Input {
        const ModuleIO *io = nullptr;
        std::shared_ptr<const Record> latest;
        std::vector<MuxedRecord> muxed;
        bool updated = false;
    };

    Pass(std::vector<Input> inputs, const std::vector<ModuleIO> &outputs,
         std::chrono::nanoseconds delta, std::uint64_t number);

    // Since the previous pass began (0 for the first).
    std::chrono::nanoseconds delta_time() const noexcept
    {
        return delta_;
    }
    // 1 for the module's first pass.
    std::uint64_t number() const noexcept
    {
        return number_;
    }

    // The latest record of `input`, nullptr before the first one arrived. ubii::NotFound for a
    // name the module does not declare.
    const Record *record(std::string_view input) const;
    // Its value as a T: ubii::NotFound if no record arrived yet, ubii::WrongType for another type.
    template <class T> const T &input(std::string_view name) const
    {
        const Record *latest = record(name);
        if (latest == nullptr)
            throw_no_record(name);
        return latest->as<T>();
    }
    // Whether `input` received a record since the previous pass.
    bool updated(std::string_view input) const;
    // A mux input's latest record per matching topic, in the order the topics first appeared.
    const std::vector<MuxedRecord> &muxed(std::string_view input) const;

    // Sets `output` to `value` (0, false and "" included): published after the pass, each output
    // once, the last value set. ubii::NotFound for an undeclared output, ubii::WrongType for a
    // value of another member than its message format.
    void set_output(std::string_view output, Value value);
    template <class T> void set_output(std::string_view output, T &&value)
    {
        set_output(output, Value(std::forward<T>(value)));
    }
    // Adds one element to `output` for a demultiplexer (a session's TopicDemux): published on the
    // topic its format makes of `topic_params`. Every element added is published, in order.
    // The same errors as set_output; ubii::StateError if set_output set the output already.
    void add_demuxed_output(std::string_view output, Value value,
                            std::vector<std::string> topic_params);
    const std::vector<PassOutput> &outputs() const noexcept
    {
        return outputs_;
    }
    std::vector<PassOutput> take_outputs() noexcept
    {
        return std::move(outputs_);
    }

    // A line for the node's log (Scheduler::on_log; `ubii-node run` prints it with the module's
    // id): what a library inside the module says, such as Tesseract's warnings. Handed on after
    // the pass, from the thread that polls, whether the pass returned or threw.
    void log(std::string line);
    std::vector<std::string> take_log() noexcept
    {
        return std::move(log_);
    }

  private:
    const Input &find(std::string_view input) const;
    void check_output(std::string_view output, const Value &value) const;
    [[noreturn]] static void throw_no_record(std::string_view input);

    std::vector<Input> inputs_;
    const std::vector<ModuleIO> *declared_outputs_;
    std::vector<PassOutput> outputs_;
    std::vector<std::string> log_;
    std::chrono::nanoseconds delta_;
    std::uint64_t number_;
};

class ProcessingModule
{
  public:
    explicit ProcessingModule(ModuleDescription description);
    virtual ~ProcessingModule();
    ProcessingModule(const ProcessingModule &) = delete;
    ProcessingModule &operator=(const ProcessingModule &) = delete;

    const ModuleDescription &description() const noexcept
    {
        return description_;
    }
    const std::string &name() const noexcept
    {
        return description_.name;
    }
    ProcessingStatus status() const noexcept
    {
        return lifecycle_.state();
    }
    // The module's id: a master's in a session, else the scheduler's ("<name>#<n>") once added.
    const std::string &id() const noexcept
    {
        return id_;
    }
    // In a session: the session's id and the id of the node the master assigned the module to
    // ("" otherwise).
    const std::string &session_id() const noexcept
    {
        return session_id_;
    }
    const std::string &node_id() const noexcept
    {
        return node_id_;
    }
    // The lifecycle as a protocol (INITIALIZED -> CREATED -> PROCESSING <-> HALTED -> DESTROYED):
    // hook its transitions to watch a module.
    ProcessingProtocol &lifecycle() noexcept
    {
        return lifecycle_;
    }
    // The module as Ubi-Interact describes it (ubii.processing.ProcessingModule, language CPP).
    ProcessingModuleSpec spec() const;

  protected:
    // The module is about to be scheduled for the first time. What it throws keeps it from
    // being created.
    virtual void on_created()
    {
    }
    // One pass. What it throws is caught, reported with the module's name, counted
    // (Timing::errors), and the outputs set before it are not published.
    virtual void on_processing(Pass &pass) = 0;
    virtual void on_halted()
    {
    }
    virtual void on_destroyed()
    {
    }

  private:
    friend class detail::ModuleRunner;
    friend class detail::SessionHost;
    ModuleDescription description_;
    ProcessingProtocol lifecycle_;
    std::string id_;
    std::string session_id_;
    std::string node_id_;
};

// A module whose pass is a function, for modules too small to deserve a class.
std::unique_ptr<ProcessingModule> make_module(ModuleDescription description,
                                              std::function<void(Pass &)> on_processing);

} // namespace ubii

#endif
