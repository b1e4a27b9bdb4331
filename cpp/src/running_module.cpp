#include "ubii/running_module.hpp"

#include "node_core.hpp"

namespace ubii
{

Wiring &Wiring::input(std::string input, std::string topic)
{
    inputs_.push_back(Input{std::move(input), std::move(topic), false, {}, RecordType::NONE});
    return *this;
}

Wiring &Wiring::mux_input(std::string input, std::string topic_regex, std::string identity_pattern,
                          RecordType data_type)
{
    inputs_.push_back(Input{std::move(input), std::move(topic_regex), true,
                            std::move(identity_pattern), data_type});
    return *this;
}

Wiring &Wiring::output(std::string output, std::string topic)
{
    outputs_.push_back(Output{std::move(output), std::move(topic), false, RecordType::NONE});
    return *this;
}

Wiring &Wiring::demux_output(std::string output, std::string topic_format, RecordType data_type)
{
    outputs_.push_back(Output{std::move(output), std::move(topic_format), true, data_type});
    return *this;
}

std::string demux_topic(std::string_view format, const std::vector<std::string> &params)
{
    static constexpr std::string_view open = "{{#", close = "}}";
    std::string topic;
    std::size_t at = 0;
    for (;;) {
        const std::size_t start = format.find(open, at);
        const std::size_t end =
            start == std::string_view::npos ? start : format.find(close, start + open.size());
        if (end == std::string_view::npos) {
            topic.append(format.substr(at));
            return topic;
        }
        const std::string_view digits =
            format.substr(start + open.size(), end - start - open.size());
        const bool numeric = !digits.empty() && digits.size() < 6 &&
                             digits.find_first_not_of("0123456789") == std::string_view::npos;
        topic.append(format.substr(at, start - at));
        if (!numeric) { // not a placeholder: kept as it is
            topic.append(format.substr(start, end + close.size() - start));
        } else {
            const std::size_t index = std::stoul(std::string(digits));
            if (index >= params.size())
                throw InvalidArgument("topic format \"" + std::string(format) +
                                      "\" needs parameter " + std::to_string(index) +
                                      ", the element has " + std::to_string(params.size()));
            topic.append(params[index]);
        }
        at = end + close.size();
    }
}

RunningModule::RunningModule(std::weak_ptr<detail::NodeCore> node, std::string id)
    : node_(std::move(node)), id_(std::move(id))
{
}

RunningModule::RunningModule(RunningModule &&other) noexcept
    : node_(std::move(other.node_)), id_(std::move(other.id_))
{
    other.node_.reset();
}

RunningModule &RunningModule::operator=(RunningModule &&other) noexcept
{
    if (this != &other) {
        remove();
        node_ = std::move(other.node_);
        id_ = std::move(other.id_);
        other.node_.reset();
    }
    return *this;
}

RunningModule::~RunningModule()
{
    remove();
}

std::shared_ptr<detail::NodeCore> RunningModule::lock() const
{
    auto node = node_.lock();
    if (!node || !node->scheduler().contains(id_))
        throw StateError("processing module " + id_ + " is no longer on its node");
    return node;
}

bool RunningModule::active() const noexcept
{
    auto node = node_.lock();
    return node && node->scheduler().contains(id_);
}

ProcessingStatus RunningModule::status() const noexcept
{
    auto node = node_.lock();
    if (!node || !node->scheduler().contains(id_))
        return ProcessingStatus::destroyed;
    return node->scheduler().module(id_).status();
}

Timing RunningModule::timing() const
{
    return lock()->scheduler().timing(id_);
}

ProcessingModule &RunningModule::module() const
{
    return lock()->scheduler().module(id_);
}

void RunningModule::start()
{
    lock()->scheduler().start(id_);
}

void RunningModule::halt()
{
    lock()->scheduler().halt(id_);
}

void RunningModule::remove() noexcept
{
    if (auto node = node_.lock())
        node->remove_module(id_);
    node_.reset();
}

void RunningModule::release() noexcept
{
    node_.reset();
}

} // namespace ubii
