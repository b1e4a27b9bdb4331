#include "ubii/node.hpp"

#include <algorithm>
#include <cstring>

#include "node_core.hpp"
#include "publish.hpp"
#include "ubii/image.h"
#include "ubii/master.hpp"

namespace ubii
{

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

bool Node::subscriptions_pending() const noexcept
{
    return ubii_subscriptions_pending(core_->c_node());
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

bool Node::implements(Behaviour) const noexcept
{
    return true;
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

#define UBII_CPP_PUBLISH_FORWARD(method, type)                                                     \
    Status Node::method(TopicRef topic, type value) noexcept                                       \
    {                                                                                              \
        return detail::method(*core_, topic, value);                                               \
    }
UBII_CPP_PUBLISH_FORWARD(publish_double, double)
UBII_CPP_PUBLISH_FORWARD(publish_float, float)
UBII_CPP_PUBLISH_FORWARD(publish_int32, std::int32_t)
UBII_CPP_PUBLISH_FORWARD(publish_bool, bool)
UBII_CPP_PUBLISH_FORWARD(publish_string, std::string_view)
UBII_CPP_PUBLISH_FORWARD(publish_image, const ImageView &)
UBII_CPP_PUBLISH_FORWARD(publish_value, const Value &)
#undef UBII_CPP_PUBLISH_FORWARD

Status Node::publish_message(TopicRef topic, RecordType type,
                             const google::protobuf::MessageLite &message) noexcept
{
    return detail::publish_message(*core_, topic, type, message);
}

RunningModule Node::run(std::unique_ptr<ProcessingModule> module, const Wiring &wiring)
{
    std::string id = core_->run_module(std::move(module), wiring);
    return RunningModule(core_, std::move(id));
}

Scheduler &Node::scheduler() noexcept
{
    return core_->scheduler();
}

int Node::pollfds(ubii_pollfd *fds, int capacity) noexcept
{
    return ubii_node_pollfds(core_->c_node(), fds, capacity);
}

std::optional<std::chrono::nanoseconds> Node::next_timeout() const
{
    std::optional<std::chrono::nanoseconds> timeout;
    const int core_timeout = ubii_node_next_timeout_ms(core_->c_node());
    if (core_timeout >= 0)
        timeout = std::chrono::milliseconds(core_timeout);
    if (const auto due = core_->until_due())
        timeout = timeout ? std::min(*timeout, *due) : *due;
    return timeout;
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

void Node::serve_sessions(ModuleRegistry modules)
{
    core_->session_host().serve(std::move(modules));
}

void Node::on_session_event(SessionEventHandler handler)
{
    core_->session_host().on_event(std::move(handler));
}

std::vector<SessionModule> Node::session_modules() const
{
    const detail::SessionHost *host = core_->session_host_if_any();
    return host != nullptr ? host->modules() : std::vector<SessionModule>{};
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
