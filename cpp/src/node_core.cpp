#include "node_core.hpp"

#include "publish.hpp"

#include <algorithm>
#include <type_traits>
#include <cstring>
#include <limits>

namespace ubii::detail
{

namespace
{

ConnectionState from_core(ubii_state state) noexcept
{
    switch (state) {
    case UBII_STATE_STOPPED:
        return ConnectionState::stopped;
    case UBII_STATE_CONNECTING:
        return ConnectionState::connecting;
    case UBII_STATE_REGISTERING:
        return ConnectionState::registering;
    case UBII_STATE_OPENING:
        return ConnectionState::opening;
    case UBII_STATE_READY:
        return ConnectionState::preparing; // ready once the hooks on preparing have settled
    case UBII_STATE_RECONNECTING:
        return ConnectionState::reconnecting;
    case UBII_STATE_STOPPING:
        return ConnectionState::stopping;
    case UBII_STATE_FAILED:
        return ConnectionState::failed;
    }
    return ConnectionState::failed;
}

// The transitions the core makes, with `preparing` between its READY and the node's ready.
std::vector<std::pair<ConnectionState, ConnectionState>> connection_transitions()
{
    using S = ConnectionState;
    std::vector<std::pair<S, S>> allowed = {
        {S::stopped, S::connecting},  {S::failed, S::connecting},
        {S::failed, S::stopped},      {S::connecting, S::registering},
        {S::registering, S::opening}, {S::opening, S::preparing},
        {S::preparing, S::ready},     {S::reconnecting, S::connecting},
        {S::stopping, S::stopped},
    };
    for (S from : {S::connecting, S::registering, S::opening, S::preparing, S::ready}) {
        for (S to : {S::reconnecting, S::stopping, S::stopped, S::failed})
            allowed.emplace_back(from, to);
    }
    for (S to : {S::stopping, S::stopped, S::failed})
        allowed.emplace_back(S::reconnecting, to);
    return allowed;
}

std::uint32_t milliseconds_u32(std::chrono::milliseconds value)
{
    const auto count = value.count();
    if (count <= 0)
        return 0;
    return count > std::numeric_limits<std::uint32_t>::max()
               ? std::numeric_limits<std::uint32_t>::max()
               : static_cast<std::uint32_t>(count);
}

int milliseconds_int(std::chrono::milliseconds value)
{
    const auto count = value.count();
    if (count <= 0)
        return 0;
    return count > std::numeric_limits<int>::max() ? std::numeric_limits<int>::max()
                                                   : static_cast<int>(count);
}

// A mux input's identity for `topic`: the first capture group of `pattern` searched in it, the
// whole match without a group, or the topic without a pattern (or a match).
std::string identity_of(std::string_view topic, const std::regex *pattern)
{
    std::string identity(topic);
    std::smatch match;
    if (pattern != nullptr && std::regex_search(identity, match, *pattern))
        return match.size() > 1 ? match[1].str() : match[0].str();
    return identity;
}

} // namespace

template <class Where, class F> void NodeCore::guard(const Where &where, F &&code) noexcept
{
    try {
        code();
    } catch (...) {
        const std::exception_ptr error = std::current_exception();
        try {
            if constexpr (std::is_invocable_v<const Where &>)
                report_exception(where(), error);
            else
                report_exception(where, error);
        } catch (...) { // building the text failed: report what can be said without it
            report_exception("a callback", error);
        }
    }
}

NodeCore::NodeCore(NodeOptions options, const ubii_port *port)
    : options_(std::move(options)),
      protocol_("connection", ConnectionState::stopped, connection_transitions(),
                [](ConnectionState state) { return to_string(state); })
{
    if (port != nullptr) {
        port_ = *port;
    } else {
        owned_port_ = std::make_unique<LinuxPortOwner>(options_);
        port_ = owned_port_->port();
    }
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = options_.service_url.c_str();
    config.topic_url = options_.topic_url.empty() ? nullptr : options_.topic_url.c_str();
    config.client_name = options_.name.c_str();
    config.is_dedicated_processing_node = options_.is_dedicated_processing_node;
    config.service_timeout_ms = milliseconds_u32(options_.service_timeout);
    config.ping_timeout_ms = milliseconds_u32(options_.ping_timeout);
    config.reconnect_min_ms = milliseconds_u32(options_.reconnect.first_delay);
    config.reconnect_max_ms = milliseconds_u32(options_.reconnect.max_delay);
    config.max_reconnect_attempts = options_.reconnect.max_attempts;
    config.stamp_records = options_.stamp_records;
    config.on_state = &NodeCore::on_state;
    config.on_state_user = this;
    config.on_error = &NodeCore::on_error;
    config.on_error_user = this;
    node_ = std::make_unique<ubii_node>();
    check(ubii_node_init(node_.get(), sizeof(ubii_node), &config, port_),
          "cannot set the node up (service URL \"" + options_.service_url + "\", name \"" +
              options_.name + "\")");
    scheduler_ = std::make_unique<Scheduler>();
    scheduler_->on_output([this](const ProcessingModule &module, const PassOutput &output) {
        return publish_output(module, output);
    });
    scheduler_->on_error(
        [this](Status status, std::string_view detail) { report(status, std::string(detail)); });
    if (owned_port_)
        scheduler_->set_waker([port = owned_port_.get()] { port->wake(); });
    protocol_.on_every_transition([this](ConnectionTransition &transition) {
        if (state_handler_)
            state_handler_(transition.from(), transition.to(), last_reason_);
    });
    protocol_.set_error_handler(
        [this](std::exception_ptr error, const ConnectionTransition &transition) {
            report_exception("a hook on " + std::string(to_string(transition.from())) + " -> " +
                                 std::string(to_string(transition.to())),
                             std::move(error));
        });
}

NodeCore::~NodeCore()
{
    // The application's handlers may refer to objects already gone: none of them runs from here.
    destroying_ = true;
    state_handler_ = nullptr;
    error_handler_ = nullptr;
    waiting_.clear();
    if (session_host_)
        session_host_->clear();
    scheduler_.reset(); // joins worker threads; their modules' on_destroyed runs here
    module_wirings_.clear();
    if (ubii_node_state(node_.get()) != UBII_STATE_STOPPED)
        ubii_node_stop_wait(node_.get(), milliseconds_int(options_.stop_timeout));
    // The port (owned_port_) is destroyed after the node is stopped: members go in reverse order.
}

std::string NodeCore::transport_error() const
{
    return owned_port_ ? owned_port_->last_error() : std::string();
}

void NodeCore::start()
{
    const ubii_status status = ubii_node_start(node_.get());
    if (status != UBII_OK)
        throw_status(to_status(status),
                     "cannot start the node for " + options_.service_url +
                         (options_.topic_url.empty() ? std::string() : " / " + options_.topic_url));
}

void NodeCore::poll(std::chrono::milliseconds timeout)
{
    if (poll_depth_ > 0)
        throw StateError("ubii::Node::poll called from inside one of the node's callbacks");
    ++poll_depth_;
    try {
        wait_for_io(timeout);
    } catch (...) {
        --poll_depth_;
        throw;
    }
    --poll_depth_;
}

// Waits for I/O no longer than the next due pass: the port's poll to within the last millisecond
// (its timeout is whole milliseconds), then a sleep to the deadline itself, so that frequency
// passes start on time rather than up to a millisecond late.
void NodeCore::wait_for_io(std::chrono::milliseconds timeout)
{
    using std::chrono::milliseconds;
    std::chrono::nanoseconds wait = timeout;
    const std::optional<std::chrono::nanoseconds> due = until_due();
    const bool pass_first = due && *due < wait;
    if (pass_first)
        wait = *due;
    const milliseconds port_wait = pass_first ? std::chrono::floor<milliseconds>(wait) : timeout;
    const ubii_status status = ubii_node_poll(node_.get(), milliseconds_int(port_wait));
    after_poll();
    if (status != UBII_OK)
        throw_status(to_status(status), "ubii_node_poll");
    if (pass_first) {
        const std::optional<Clock::time_point> next = scheduler_->next_due();
        const Clock::time_point now = scheduler_->clock().now();
        if (next && *next > now && *next - now <= milliseconds(1))
            scheduler_->clock().sleep_until(*next);
    }
    if (scheduler_->empty())
        return;
    guard("the processing module scheduler", [this] { scheduler_->run_due(); });
    retired_.clear();
}

std::optional<std::chrono::nanoseconds> NodeCore::until_due() const
{
    const std::optional<Clock::time_point> due = scheduler_->next_due();
    if (!due)
        return std::nullopt;
    return std::max(std::chrono::nanoseconds(0), *due - scheduler_->clock().now());
}

bool NodeCore::stop_wait(std::chrono::milliseconds timeout)
{
    if (poll_depth_ > 0)
        throw StateError("ubii::Node::stop_wait called from inside one of the node's callbacks");
    ++poll_depth_;
    const ubii_status status = ubii_node_stop_wait(node_.get(), milliseconds_int(timeout));
    after_poll();
    --poll_depth_;
    return status == UBII_OK;
}

void NodeCore::after_poll()
{
    settle();
    if (!waiting_.empty()) {
        std::vector<std::pair<Behaviour, std::function<void()>>> due;
        auto usable_now = [this](const auto &entry) { return usable(entry.first); };
        std::copy_if(waiting_.begin(), waiting_.end(), std::back_inserter(due), usable_now);
        waiting_.erase(std::remove_if(waiting_.begin(), waiting_.end(), usable_now),
                       waiting_.end());
        for (auto &entry : due)
            guard([&entry] { return "when_usable(" + std::string(to_string(entry.first)) + ")"; },
                  entry.second);
    }
    retired_.clear();
}

void NodeCore::settle()
{
    if (protocol_.state() == ConnectionState::preparing && protocol_.settled() &&
        ubii_node_state(node_.get()) == UBII_STATE_READY) {
        last_reason_ = Status::ok;
        protocol_.transition(ConnectionState::ready);
    }
}

void NodeCore::mirror(ubii_state current, ubii_status reason)
{
    const ConnectionState previous = protocol_.state();
    const ConnectionState next = from_core(current);
    if (next == previous)
        return;
    last_reason_ = to_status(reason);
    if (protocol_.allows(previous, next)) {
        protocol_.transition(next);
    } else {
        report(Status::state, "the core went from " + std::string(to_string(previous)) + " to " +
                                  std::string(to_string(next)) +
                                  ", which the connection protocol does not list");
        protocol_.force(next);
    }
    settle();
}

void NodeCore::on_state(ubii_node *, ubii_state, ubii_state current, ubii_status reason, void *user)
{
    auto *core = static_cast<NodeCore *>(user);
    if (core->destroying_)
        return;
    core->guard(std::string("the connection protocol"), [&] { core->mirror(current, reason); });
}

void NodeCore::on_error(ubii_node *, ubii_status status, const char *detail, void *user)
{
    static_cast<NodeCore *>(user)->report(to_status(status), detail != nullptr ? detail : "");
}

void NodeCore::on_record(ubii_node *, const ubii_record *record, void *user)
{
    auto *handler = static_cast<Handler *>(user);
    if (!handler->active || handler->core->destroying_)
        return;
    const Record lent = Record::lend(*record);
    handler->core->guard([handler] { return "the subscription to " + handler->pattern; },
                         [&] { handler->fn(lent); });
}

void NodeCore::on_reply(ubii_node *, const ubii_reply *reply, void *user)
{
    auto *pending = static_cast<PendingCall *>(user);
    NodeCore *core = pending->core;
    auto owned = core->calls_.find(pending);
    if (owned == core->calls_.end())
        return;
    std::unique_ptr<PendingCall> call = std::move(owned->second);
    core->calls_.erase(owned);
    if (core->destroying_)
        return; // documented: calls pending when the node is destroyed stay unresolved

    std::optional<Result<ServiceReply>> outcome;
    try {
        switch (reply->status) {
        case UBII_OK: {
            ServiceReply parsed;
            const auto *member =
                ServiceReply::descriptor()->FindFieldByNumber(static_cast<int>(reply->member));
            if (member == nullptr || member->message_type() == nullptr)
                throw UnexpectedReply(call->service + ": the reply's member " +
                                      std::to_string(reply->member) + " is not in the schema");
            auto *message = parsed.GetReflection()->MutableMessage(&parsed, member);
            if (reply->size > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
                !message->ParseFromArray(reply->bytes, static_cast<int>(reply->size)))
                throw DecodeError(call->service + ": the reply's " + member->name() +
                                  " is not valid protobuf");
            outcome.emplace(Result<ServiceReply>::success(std::move(parsed)));
            break;
        }
        case UBII_ERR_BROKER:
            throw ServiceError(call->service, reply->error_title, reply->error_message);
        case UBII_ERR_TIMEOUT:
            throw Timeout(call->service + ": no reply within " +
                          std::to_string(call->timeout.count() > 0
                                             ? call->timeout.count()
                                             : core->options_.service_timeout.count()) +
                          " ms");
        case UBII_ERR_CANCELLED:
            throw Cancelled(call->service +
                            ": cancelled (the node stopped or lost its connection)");
        default:
            throw_status(to_status(reply->status), call->service);
        }
    } catch (...) {
        outcome.emplace(Result<ServiceReply>::failure(std::current_exception()));
    }
    core->guard([&call] { return "the reply of " + call->service; },
                [&] { call->resolve(std::move(*outcome)); });
}

std::uint64_t NodeCore::subscribe(std::string pattern, bool regex, Node::RecordHandler fn)
{
    if (!fn)
        throw InvalidArgument("subscribe(" + pattern + "): no handler");
    auto handler = std::make_unique<Handler>();
    handler->core = this;
    handler->id = ++next_handler_id_;
    handler->fn = std::move(fn);
    handler->pattern = pattern;
    const ubii_status status =
        regex ? ubii_subscribe_regex(node_.get(), pattern.c_str(), &NodeCore::on_record,
                                     handler.get(), &handler->c_handle)
              : ubii_subscribe(node_.get(), pattern.c_str(), &NodeCore::on_record, handler.get(),
                               &handler->c_handle);
    if (status != UBII_OK)
        throw_status(to_status(status),
                     std::string(regex ? "subscribe_regex(" : "subscribe(") + pattern + ")");
    const std::uint64_t id = handler->id;
    handlers_.emplace(id, std::move(handler));
    return id;
}

void NodeCore::unsubscribe(std::uint64_t id) noexcept
{
    auto found = handlers_.find(id);
    if (found == handlers_.end())
        return;
    std::unique_ptr<Handler> handler = std::move(found->second);
    handlers_.erase(found);
    handler->active = false;
    ubii_unsubscribe(node_.get(), handler->c_handle);
    // Its callback may be running right now: freed after the poll.
    if (poll_depth_ > 0) {
        try {
            retired_.push_back(std::move(handler));
        } catch (...) {
            handler.release(); // NOLINT: leaking one handler beats freeing it under its caller
        }
    }
}

bool NodeCore::subscribed(std::uint64_t id) const noexcept
{
    return handlers_.count(id) != 0;
}

void NodeCore::queue_call(const ServiceRequest &request, std::chrono::milliseconds timeout,
                          std::function<void(Result<ServiceReply>)> resolve)
{
    std::string bytes;
    if (!request.SerializeToString(&bytes))
        throw EncodeError(request.topic() + ": the request cannot be encoded");
    auto pending = std::make_unique<PendingCall>();
    pending->core = this;
    pending->service = request.topic();
    pending->timeout = timeout;
    pending->resolve = std::move(resolve);
    const ubii_status status = ubii_call_encoded(
        node_.get(), reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size(),
        milliseconds_u32(timeout), &NodeCore::on_reply, pending.get());
    if (status != UBII_OK)
        throw_status(to_status(status), "cannot call " + request.topic());
    const PendingCall *key = pending.get();
    calls_.emplace(key, std::move(pending));
}

std::string NodeCore::run_module(std::unique_ptr<ProcessingModule> module, const Wiring &wiring)
{
    if (!module)
        throw InvalidArgument("Node::run without a module");
    const ModuleDescription &description = module->description();
    ModuleWiring wired;
    for (const Wiring::Input &input : wiring.inputs()) {
        if (find_io(description.inputs, input.input) == nullptr)
            throw NotFound("processing module \"" + description.name + "\" has no input \"" +
                           input.input + "\" to wire to " + input.topic);
    }
    for (const Wiring::Output &output : wiring.outputs()) {
        if (find_io(description.outputs, output.output) == nullptr)
            throw NotFound("processing module \"" + description.name + "\" has no output \"" +
                           output.output + "\" to wire to " + output.topic);
        wired.outputs[output.output] = output;
    }
    // Compiled before the module is added, so that a bad pattern leaves nothing behind.
    std::vector<std::shared_ptr<const std::regex>> identities(wiring.inputs().size());
    for (std::size_t i = 0; i < wiring.inputs().size(); ++i) {
        const Wiring::Input &input = wiring.inputs()[i];
        if (!input.mux || input.identity_pattern.empty())
            continue;
        try {
            identities[i] = std::make_shared<const std::regex>(input.identity_pattern);
        } catch (const std::regex_error &error) {
            throw InvalidArgument("identity pattern \"" + input.identity_pattern +
                                  "\" of input \"" + input.input + "\": " + error.what());
        }
    }
    // TopicMux.data_type, else the input's own message format: a filter, not an error.
    const auto mux_filter = [&description](const Wiring::Input &input) {
        const RecordType own = find_io(description.inputs, input.input)->type();
        if (input.data_type != RecordType::NONE && own != RecordType::NONE &&
            input.data_type != own)
            throw InvalidArgument("mux input \"" + input.input + "\" takes " +
                                  std::string(message_format(own)) + ", not " +
                                  std::string(message_format(input.data_type)));
        return input.data_type != RecordType::NONE ? input.data_type : own;
    };
    std::vector<RecordType> filters(wiring.inputs().size(), RecordType::NONE);
    for (std::size_t i = 0; i < wiring.inputs().size(); ++i) {
        if (wiring.inputs()[i].mux)
            filters[i] = mux_filter(wiring.inputs()[i]);
    }

    const std::string id = scheduler_->add(std::move(module));
    try {
        for (std::size_t i = 0; i < wiring.inputs().size(); ++i) {
            const Wiring::Input &input = wiring.inputs()[i];
            if (!input.mux) {
                wired.subscriptions.push_back(subscribe(
                    input.topic, false, [this, id, name = input.input](const Record &record) {
                        scheduler_->feed(id, name, std::make_shared<const Record>(record));
                    }));
                continue;
            }
            wired.subscriptions.push_back(subscribe(
                input.topic, true,
                [this, id, name = input.input, type = filters[i],
                 identity = identities[i]](const Record &record) {
                    if (type != RecordType::NONE && type != record.type())
                        return;
                    scheduler_->feed_muxed(id, name, identity_of(record.topic(), identity.get()),
                                           std::make_shared<const Record>(record));
                }));
        }
        module_wirings_[id] = std::move(wired);
        scheduler_->start(id);
    } catch (...) {
        for (std::uint64_t subscription : wired.subscriptions)
            unsubscribe(subscription);
        module_wirings_.erase(id);
        scheduler_->remove(id);
        throw;
    }
    return id;
}

Status NodeCore::publish_output(const ProcessingModule &module, const PassOutput &output)
{
    const auto wiring = module_wirings_.find(module.id());
    if (wiring == module_wirings_.end())
        return Status::ok;
    const auto found = wiring->second.outputs.find(output.name);
    if (found == wiring->second.outputs.end())
        return Status::ok; // not wired: not published, as Wiring says
    const Wiring::Output &wired = found->second;
    if (!wired.demux)
        return publish_value(*this, wired.topic, output.value);
    if (!output.demuxed)
        throw WrongType("it is wired to the demultiplexer \"" + wired.topic +
                        "\": set its elements with Pass::add_demuxed_output");
    if (wired.data_type != RecordType::NONE && output.value.type() != wired.data_type)
        throw WrongType("its demultiplexer takes " +
                        std::string(record_type_name(wired.data_type)) + ", not " +
                        std::string(record_type_name(output.value.type())));
    return publish_value(*this, demux_topic(wired.topic, output.topic_params), output.value);
}

void NodeCore::remove_module(const std::string &id) noexcept
{
    const auto wiring = module_wirings_.find(id);
    if (wiring != module_wirings_.end()) {
        for (std::uint64_t subscription : wiring->second.subscriptions)
            unsubscribe(subscription);
        module_wirings_.erase(wiring);
    }
    if (scheduler_ && scheduler_->contains(id)) {
        try {
            scheduler_->remove(id);
        } catch (...) {
            report_exception("removing processing module " + id, std::current_exception());
        }
    }
}

bool NodeCore::usable(Behaviour behaviour) const noexcept
{
    if (behaviour == Behaviour::processing_modules && !(session_host_ && session_host_->serving()))
        return false;
    return state() == ConnectionState::ready;
}

void NodeCore::when_usable(Behaviour behaviour, std::function<void()> action)
{
    waiting_.emplace_back(behaviour, std::move(action));
}

SessionHost &NodeCore::session_host()
{
    if (!session_host_)
        session_host_ = std::make_unique<SessionHost>(*this);
    return *session_host_;
}

Stats NodeCore::stats() const noexcept
{
    ubii_stats core = {};
    ubii_node_stats(node_.get(), &core);
    Stats stats;
    stats.records_received = core.records_received;
    stats.records_published = core.records_published;
    stats.duplicates_dropped = core.duplicates_dropped;
    stats.pings = core.pings;
    stats.decode_errors = core.decode_errors;
    stats.master_errors = core.master_errors;
    stats.service_timeouts = core.service_timeouts;
    stats.reconnects = core.reconnects;
    stats.records_skipped = core.records_skipped;
    stats.callback_errors = callback_errors_;
    stats.type_mismatches = type_mismatches_;
    return stats;
}

void NodeCore::report_exception(const std::string &where, std::exception_ptr error) noexcept
{
    ++callback_errors_;
    Status status = Status::callback_threw;
    std::string what = "unknown exception";
    try {
        std::rethrow_exception(error);
    } catch (const WrongType &e) {
        ++type_mismatches_;
        status = Status::wrong_type;
        what = e.what();
    } catch (const std::exception &e) {
        what = e.what();
    } catch (...) {
    }
    try {
        report(status, where + ": " + what);
    } catch (...) {
    }
}

void NodeCore::report(Status status, const std::string &detail) noexcept
{
    if (!error_handler_ || destroying_)
        return;
    try {
        error_handler_(status, detail);
    } catch (...) {
        ++callback_errors_; // an error handler that throws has nowhere left to report to
    }
}

} // namespace ubii::detail
