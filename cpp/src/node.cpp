#include "ubii/node.hpp"

#include <algorithm>
#include <cstring>

#include "node_core.hpp"
#include "ubii/image.h"
#include "ubii/master.hpp"

namespace ubii
{

namespace
{

// A topic as the C API takes it: NUL-terminated; a view that is not is copied into a buffer of
// the node's topic limit.
class TopicText
{
  public:
    explicit TopicText(TopicRef topic)
    {
        const std::string_view view = topic.view();
        ok_ = !view.empty() && view.size() < sizeof copy_;
        if (!ok_)
            return;
        if (topic.terminated()) {
            text_ = view.data();
        } else {
            std::memcpy(copy_, view.data(), view.size());
            copy_[view.size()] = '\0';
            text_ = copy_;
        }
    }
    bool ok() const noexcept
    {
        return ok_;
    }
    const char *c_str() const noexcept
    {
        return text_;
    }

  private:
    bool ok_ = false;
    const char *text_ = "";
    char copy_[UBII_MAX_TOPIC_SIZE];
};

} // namespace

std::string_view to_string(ConnectionState state) noexcept
{
    switch (state) {
    case ConnectionState::stopped:
        return "stopped";
    case ConnectionState::connecting:
        return "connecting";
    case ConnectionState::registering:
        return "registering";
    case ConnectionState::opening:
        return "opening";
    case ConnectionState::preparing:
        return "preparing";
    case ConnectionState::ready:
        return "ready";
    case ConnectionState::reconnecting:
        return "reconnecting";
    case ConnectionState::stopping:
        return "stopping";
    case ConnectionState::failed:
        return "failed";
    }
    return "unknown";
}

// ---- Subscription -------------------------------------------------------------------------------

Subscription::Subscription(std::weak_ptr<detail::NodeCore> node, std::uint64_t id,
                           std::string pattern, bool regex)
    : node_(std::move(node)), id_(id), pattern_(std::move(pattern)), regex_(regex)
{
}

Subscription::Subscription(Subscription &&other) noexcept
    : node_(std::move(other.node_)), id_(std::exchange(other.id_, 0)),
      pattern_(std::move(other.pattern_)), regex_(other.regex_)
{
}

Subscription &Subscription::operator=(Subscription &&other) noexcept
{
    if (this != &other) {
        cancel();
        node_ = std::move(other.node_);
        id_ = std::exchange(other.id_, 0);
        pattern_ = std::move(other.pattern_);
        regex_ = other.regex_;
    }
    return *this;
}

Subscription::~Subscription()
{
    cancel();
}

void Subscription::cancel() noexcept
{
    if (auto node = node_.lock())
        node->unsubscribe(id_);
    release();
}

void Subscription::release() noexcept
{
    node_.reset();
    id_ = 0;
}

bool Subscription::active() const noexcept
{
    auto node = node_.lock();
    return node && node->subscribed(id_);
}

// ---- Node ---------------------------------------------------------------------------------------

Node::Node(NodeOptions options)
    : core_(std::make_shared<detail::NodeCore>(std::move(options), nullptr))
{
}

Node::Node(NodeOptions options, ubii_port port)
    : core_(std::make_shared<detail::NodeCore>(std::move(options), &port))
{
}

Node::Node(Node &&other) noexcept = default;
Node &Node::operator=(Node &&other) noexcept = default;
Node::~Node() = default;

const NodeOptions &Node::options() const noexcept
{
    return core_->options();
}

void Node::start()
{
    core_->start();
}

void Node::connect(std::chrono::milliseconds timeout)
{
    if (state() == ConnectionState::stopped || state() == ConnectionState::failed)
        start();
    const bool settled =
        run_until([this] { return ready() || state() == ConnectionState::failed; }, timeout);
    if (ready())
        return;
    const std::string transport = transport_error();
    const std::string where =
        options().service_url + (options().topic_url.empty() ? "" : " / " + options().topic_url);
    const std::string detail = " (node " + std::string(to_string(state())) +
                               (transport.empty() ? "" : "; " + transport) + ")";
    if (settled)
        throw NotConnected("gave up connecting to the master at " + where + detail);
    throw Timeout("the master at " + where + " was not reachable within " +
                  std::to_string(timeout.count()) + " ms" + detail);
}

void Node::poll(std::chrono::milliseconds timeout)
{
    core_->poll(timeout);
}

void Node::run_for(std::chrono::milliseconds duration)
{
    run_until([] { return false; }, duration);
}

bool Node::run_until(const std::function<bool()> &done, std::chrono::milliseconds timeout)
{
    using clock = std::chrono::steady_clock;
    const auto deadline = clock::now() + timeout;
    for (;;) {
        if (done())
            return true;
        const auto now = clock::now();
        if (now >= deadline)
            return false;
        // Short slices: `done` may depend on more than the node's own events.
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - now);
        poll(std::min(left, std::chrono::milliseconds(50)));
    }
}

void Node::stop()
{
    check(ubii_node_stop(core_->c_node()), "ubii_node_stop");
}

bool Node::stop_wait(std::optional<std::chrono::milliseconds> timeout)
{
    return core_->stop_wait(timeout.value_or(options().stop_timeout));
}

ConnectionState Node::state() const noexcept
{
    return core_->state();
}

std::string Node::client_id() const
{
    return ubii_node_client_id(core_->c_node());
}

std::string Node::transport_error() const
{
    return core_->transport_error();
}

ConnectionProtocol &Node::connection() noexcept
{
    return core_->protocol();
}

void Node::on_state(StateHandler handler)
{
    core_->set_state_handler(std::move(handler));
}

void Node::on_error(ErrorHandler handler)
{
    core_->set_error_handler(std::move(handler));
}

Stats Node::stats() const
{
    return core_->stats();
}

bool Node::implements(Behaviour behaviour) const noexcept
{
    return behaviour != Behaviour::processing_modules;
}

bool Node::usable(Behaviour behaviour) const noexcept
{
    return core_->usable(behaviour);
}

void Node::when_usable(Behaviour behaviour, std::function<void()> action)
{
    core_->when_usable(behaviour, std::move(action));
}

bool Node::wait_usable(Behaviour behaviour, std::chrono::milliseconds timeout)
{
    if (!implements(behaviour))
        throw Unsupported("ubii::Node does not implement the " + std::string(to_string(behaviour)) +
                          " behaviour");
    return run_until([this, behaviour] { return usable(behaviour); }, timeout);
}

Subscription Node::subscribe(std::string topic, RecordHandler handler)
{
    const std::uint64_t id = core_->subscribe(topic, false, std::move(handler));
    return Subscription(core_, id, std::move(topic), false);
}

Subscription Node::subscribe_regex(std::string regex, RecordHandler handler)
{
    const std::uint64_t id = core_->subscribe(regex, true, std::move(handler));
    return Subscription(core_, id, std::move(regex), true);
}

void Node::throw_unless_ok(Status status, std::string_view topic) const
{
    if (status != Status::ok)
        throw_status(status, "cannot publish on " + std::string(topic));
}

#define UBII_CPP_PUBLISH_SCALAR(method, type, c_function)                                          \
    Status Node::method(TopicRef topic, type value) noexcept                                       \
    {                                                                                              \
        const TopicText text(topic);                                                               \
        if (!text.ok())                                                                            \
            return Status::invalid_argument;                                                       \
        return to_status(c_function(core_->c_node(), text.c_str(), value));                        \
    }
UBII_CPP_PUBLISH_SCALAR(publish_double, double, ubii_publish_double)
UBII_CPP_PUBLISH_SCALAR(publish_float, float, ubii_publish_float)
UBII_CPP_PUBLISH_SCALAR(publish_int32, std::int32_t, ubii_publish_int32)
UBII_CPP_PUBLISH_SCALAR(publish_bool, bool, ubii_publish_bool)
#undef UBII_CPP_PUBLISH_SCALAR

Status Node::publish_string(TopicRef topic, std::string_view value) noexcept
{
    const TopicText text(topic);
    if (!text.ok())
        return Status::invalid_argument;
    return to_status(
        ubii_publish_string(core_->c_node(), text.c_str(), value.data(), value.size()));
}

Status Node::publish_image(TopicRef topic, const ImageView &image) noexcept
{
    const TopicText text(topic);
    if (!text.ok())
        return Status::invalid_argument;
    return to_status(ubii_publish_image(
        core_->c_node(), text.c_str(), image.width, image.height,
        static_cast<ubii_dataStructure_Image2D_DataFormat>(image.format), image.data, image.size));
}

Status Node::publish_message(TopicRef topic, RecordType type,
                             const google::protobuf::MessageLite &message) noexcept
{
    if (type == RecordType::IMAGE2D) { // the pixels go to the transport without a copy of ours
        const auto &image = static_cast<const Image2D &>(message);
        return publish_image(topic,
                             ImageView{image.width(), image.height(), image.data_format(),
                                       reinterpret_cast<const std::uint8_t *>(image.data().data()),
                                       image.data().size()});
    }
    const TopicText text(topic);
    if (!text.ok())
        return Status::invalid_argument;
    std::string &bytes = core_->encode_buffer();
    try {
        if (!message.SerializeToString(&bytes))
            return Status::encode;
    } catch (...) { // allocation
        return Status::encode;
    }
    return to_status(
        ubii_publish_encoded(core_->c_node(), text.c_str(), static_cast<ubii_record_type>(type),
                             reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size()));
}

Status Node::publish_value(TopicRef topic, const Value &value) noexcept
{
    const RecordType type = value.type();
    return value.visit([&](const auto &held) -> Status {
        using T = std::decay_t<decltype(held)>;
        if constexpr (std::is_same_v<T, std::monostate>)
            return Status::invalid_argument;
        else if constexpr (std::is_same_v<T, double>)
            return publish_double(topic, held);
        else if constexpr (std::is_same_v<T, float>)
            return publish_float(topic, held);
        else if constexpr (std::is_same_v<T, std::int32_t>)
            return publish_int32(topic, held);
        else if constexpr (std::is_same_v<T, bool>)
            return publish_bool(topic, held);
        else if constexpr (std::is_same_v<T, std::string>)
            return publish_string(topic, held);
        else
            return publish_message(topic, type, held);
    });
}

Call<ServiceReply> Node::call(const ServiceRequest &request, std::chrono::milliseconds timeout)
{
    return call_as<ServiceReply>(request, timeout);
}

void Node::queue_call(const ServiceRequest &request, std::chrono::milliseconds timeout,
                      std::function<void(Result<ServiceReply>)> resolve)
{
    core_->queue_call(request, timeout, std::move(resolve));
}

Master Node::master()
{
    return Master(*this);
}

Sessions Node::sessions()
{
    return Sessions(*this);
}

ubii_node *Node::c_node() noexcept
{
    return core_->c_node();
}

} // namespace ubii
