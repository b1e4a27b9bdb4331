#ifndef UBII_RUNNING_MODULE_HPP
#define UBII_RUNNING_MODULE_HPP

// Running a processing module on a ubii::Node, wired to topics by the application:
//
//     ubii::RunningModule sum = node.run(std::make_unique<Sum>(),
//                                        ubii::Wiring().input("a", "/a").input("b", "/b")
//                                                      .output("sum", "/sum"));
//     node.poll(...);                // passes run inside poll(), at their due time
//     sum.timing().intervals.mean;   // the timing metric
//
// Sessions a master starts wire modules the same way, from their IO mappings
// (Node::serve_sessions).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ubii/processing_module.hpp"
#include "ubii/record_type.hpp"
#include "ubii/timing.hpp"

namespace ubii
{

namespace detail
{
class NodeCore;
}

// Which topics feed a module's inputs and receive its outputs. An input not wired receives
// nothing; an output not wired is not published (a lockstep driver still returns it).
class Wiring
{
  public:
    struct Input {
        std::string input;
        std::string topic; // a topic, or a regex for a mux input
        bool mux = false;
        std::string identity_pattern;
        RecordType data_type = RecordType::NONE;
    };
    struct Output {
        std::string output;
        std::string topic; // a topic, or the topic format of a demultiplexed output
        bool demux = false;
        RecordType data_type = RecordType::NONE;
    };

    // Records on `topic` feed `input`.
    Wiring &input(std::string input, std::string topic);
    // Records on every topic matching `topic_regex` (the dialect of ubii/topic.h) feed `input`,
    // the latest per topic, each with an identity: the first capture group of
    // `identity_pattern` (ECMAScript) searched in the topic, its whole match without a group, or
    // the topic without a pattern. Records of another type than `data_type` (NONE: the input's
    // message format) are filtered out, as TopicMux.data_type does.
    Wiring &mux_input(std::string input, std::string topic_regex, std::string identity_pattern = {},
                      RecordType data_type = RecordType::NONE);
    // `output`'s values are published on `topic`.
    Wiring &output(std::string output, std::string topic);
    // `output`'s elements (Pass::add_demuxed_output) are published each on the topic made of
    // `topic_format` by replacing `{{#0}}`, `{{#1}}`, ... with the element's topic parameters, as
    // TopicDemux.output_topic_format does. Elements of another type than `data_type` (NONE: any
    // the output takes) are not published (Timing::outputs_failed).
    Wiring &demux_output(std::string output, std::string topic_format,
                         RecordType data_type = RecordType::NONE);

    const std::vector<Input> &inputs() const noexcept
    {
        return inputs_;
    }
    const std::vector<Output> &outputs() const noexcept
    {
        return outputs_;
    }

  private:
    std::vector<Input> inputs_;
    std::vector<Output> outputs_;
};

// The topic a demultiplexed element goes to: `format` with each `{{#n}}` replaced by
// `params[n]`. ubii::InvalidArgument if the format names a parameter the element lacks.
std::string demux_topic(std::string_view format, const std::vector<std::string> &params);

// A module running on a node. Destroying the handle (or remove()) halts and destroys the module
// and cancels its subscriptions; release() leaves it to the node. Movable.
class RunningModule
{
  public:
    RunningModule() = default;
    RunningModule(std::weak_ptr<detail::NodeCore> node, std::string id);
    RunningModule(RunningModule &&other) noexcept;
    RunningModule &operator=(RunningModule &&other) noexcept;
    RunningModule(const RunningModule &) = delete;
    RunningModule &operator=(const RunningModule &) = delete;
    ~RunningModule();

    const std::string &id() const noexcept
    {
        return id_;
    }
    // Whether the module is still on its node.
    bool active() const noexcept;
    // DESTROYED once removed (or the node is gone).
    ProcessingStatus status() const noexcept;
    // ubii::StateError once the module is removed.
    Timing timing() const;
    ProcessingModule &module() const;
    void start();
    void halt();
    void remove() noexcept;
    void release() noexcept;

  private:
    std::shared_ptr<detail::NodeCore> lock() const;

    std::weak_ptr<detail::NodeCore> node_;
    std::string id_;
};

} // namespace ubii

#endif
