#ifndef UBII_NODE_HPP
#define UBII_NODE_HPP

// ubii::Node: a Ubi-Interact client node in C++, over the C core's ubii_node.
//
//     ubii::Node node(options);                   // owns a Linux port (or runs on a ubii_port
//     given) node.connect(5s);                           // start, and poll until ready (or throw)
//     auto sub = node.subscribe<ubii::Vector3>("/hand", [](const ubii::Vector3 &v,
//                                                          const ubii::RecordInfo &info) { ... });
//     node.publish("/speed", 1.5);
//     ubii::Server server = node.wait(node.master().server_configuration(), 2s);
//     for (;;) node.poll(16ms);                   // or poll(0ms) from a frame tick
//
// Single-threaded like the core: nothing happens and no callback runs except inside poll() (and
// the calls that poll: run_for, run_until, connect, wait, wait_usable, stop_wait, the destructor).
// An exception thrown by the application's callback never reaches the C core: it is caught,
// counted (Stats::callback_errors) and reported through on_error.
//
// Which calls throw: configuration and set-up (constructor, start, subscribe) throw ubii::Error
// subclasses; publish() throws ubii::NotConnected, ubii::WouldBlock, ...; try_publish() never
// throws and returns ubii::Status, for hot paths. Calls return ubii::Call<T>, resolved in poll().
//
// Move-only. The destructor stops the node, deregistering it within NodeOptions::stop_timeout.

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "ubii/behaviour.hpp"
#include "ubii/error.hpp"
#include "ubii/messages.hpp"
#include "ubii/module_registry.hpp"
#include "ubii/node_options.hpp"
#include "ubii/port.h"
#include "ubii/protocol.hpp"
#include "ubii/record.hpp"
#include "ubii/running_module.hpp"
#include "ubii/scheduler.hpp"
#include "ubii/service_call.hpp"
#include "ubii/session_events.hpp"

struct ubii_node;

namespace ubii
{

namespace detail
{
class NodeCore;
}
class Master;
class Sessions;

// The connection lifecycle: the core's states, and `preparing` between the core being ready and
// the node counting as ready, while hooks on it hold the step open (see Node::connection()).
enum class ConnectionState {
    stopped,
    connecting,
    registering,
    opening,
    preparing,
    ready,
    reconnecting,
    stopping,
    failed
};
std::string_view to_string(ConnectionState state) noexcept;

using ConnectionProtocol = Protocol<ConnectionState>;
using ConnectionTransition = Transition<ConnectionState>;

struct Stats {
    std::uint64_t records_received = 0;
    std::uint64_t records_published = 0;
    std::uint64_t duplicates_dropped = 0;
    std::uint64_t pings = 0;
    std::uint64_t decode_errors = 0;
    std::uint64_t master_errors = 0;
    std::uint64_t service_timeouts = 0;
    std::uint64_t reconnects = 0;
    std::uint64_t records_skipped = 0;
    // The C++ layer's own: exceptions thrown by the application's callbacks (type mismatches of
    // typed subscriptions included), and records a typed subscription could not take.
    std::uint64_t callback_errors = 0;
    std::uint64_t type_mismatches = 0;
};

// A topic as the publishing calls take it: from a C string or std::string it is passed to the core
// as it is; a std::string_view (not NUL-terminated) is copied first, into a buffer on the stack.
class TopicRef
{
  public:
    TopicRef(const char *topic) : view_(topic != nullptr ? topic : ""), terminated_(true)
    {
    }
    TopicRef(const std::string &topic) : view_(topic), terminated_(true)
    {
    }
    TopicRef(std::string_view topic) : view_(topic), terminated_(false)
    {
    }
    std::string_view view() const noexcept
    {
        return view_;
    }
    bool terminated() const noexcept
    {
        return terminated_;
    }

  private:
    std::string_view view_;
    bool terminated_;
};

// A subscription of a callback to a topic or regex. Unsubscribes when destroyed or cancel()led:
// the master stops forwarding once no subscription of the node wants the topic. Movable.
class Subscription
{
  public:
    Subscription() = default;
    Subscription(std::weak_ptr<detail::NodeCore> node, std::uint64_t id, std::string pattern,
                 bool regex);
    Subscription(Subscription &&other) noexcept;
    Subscription &operator=(Subscription &&other) noexcept;
    Subscription(const Subscription &) = delete;
    Subscription &operator=(const Subscription &) = delete;
    ~Subscription();

    // Unsubscribes now (also from inside its own callback). No effect once the node is gone.
    void cancel() noexcept;
    // Gives the subscription up to the node: it lasts as long as the node does.
    void release() noexcept;
    bool active() const noexcept;
    const std::string &pattern() const noexcept
    {
        return pattern_;
    }
    bool regex() const noexcept
    {
        return regex_;
    }

  private:
    std::weak_ptr<detail::NodeCore> node_;
    std::uint64_t id_ = 0;
    std::string pattern_;
    bool regex_ = false;
};

class Node
{
  public:
    using RecordHandler = std::function<void(const Record &)>;
    using StateHandler =
        std::function<void(ConnectionState previous, ConnectionState current, Status reason)>;
    using ErrorHandler = std::function<void(Status status, std::string_view detail)>;
    using SessionEventHandler = std::function<void(const SessionEvent &)>;

    // Creates the Linux port (ubii::Error if libzmq or libwebsockets cannot start).
    explicit Node(NodeOptions options = {});
    // Runs on `port`, which the application owns and which must outlive the node.
    Node(NodeOptions options, ubii_port port);
    Node(Node &&other) noexcept;
    Node &operator=(Node &&other) noexcept;
    Node(const Node &) = delete;
    Node &operator=(const Node &) = delete;
    ~Node();

    const NodeOptions &options() const noexcept;

    // ---- lifecycle ----------------------------------------------------------------------------
    // Begins connecting (non-blocking); ubii::Unsupported for a URL scheme the port lacks.
    void start();
    // start(), then polls until ready: ubii::Timeout (with the transport's last error) if not
    // within `timeout`, ubii::NotConnected if the node gave up (failed).
    void connect(std::chrono::milliseconds timeout = std::chrono::seconds(10));
    // Does all due I/O and callbacks, waiting at most `timeout` for something to happen (0: not at
    // all). ubii::StateError from inside a callback.
    void poll(std::chrono::milliseconds timeout = std::chrono::milliseconds(0));
    void run_for(std::chrono::milliseconds duration);
    // Polls until `done()` holds (true) or `timeout` passes (false).
    bool run_until(const std::function<bool()> &done, std::chrono::milliseconds timeout);
    // Begins stopping (non-blocking): subscriptions released at the master, client deregistered.
    void stop();
    // stop(), then polls until stopped or the timeout (NodeOptions::stop_timeout by default);
    // false if the master did not confirm in time (the node is closed anyway).
    bool stop_wait(std::optional<std::chrono::milliseconds> timeout = std::nullopt);

    ConnectionState state() const noexcept;
    bool ready() const noexcept
    {
        return state() == ConnectionState::ready;
    }
    // The id the master gave this client ("" until registered).
    std::string client_id() const;
    // The Linux port's last transport failure, e.g. why a connection was refused ("" if none, or
    // if the node runs on a port of the application's).
    std::string transport_error() const;
    // The connection lifecycle as a protocol: hook its transitions, e.g. hold `preparing` open
    // until devices are registered. Hooks run inside poll(), on every (re)connection.
    ConnectionProtocol &connection() noexcept;
    void on_state(StateHandler handler);
    // Trouble that belongs to no call: error replies to the node's own requests, undecodable
    // messages, exceptions from the application's callbacks (Status::callback_threw, or
    // Status::wrong_type for a typed subscription's mismatch).
    void on_error(ErrorHandler handler);
    Stats stats() const;

    // ---- behaviours ---------------------------------------------------------------------------
    bool implements(Behaviour behaviour) const noexcept;
    bool usable(Behaviour behaviour) const noexcept;
    // Runs `action` once, inside poll(), as soon as `behaviour` is usable (at the next poll if it
    // is now). ubii::Unsupported for a behaviour the node does not implement.
    void when_usable(Behaviour behaviour, std::function<void()> action);
    // Polls until `behaviour` is usable; false after `timeout`.
    bool wait_usable(Behaviour behaviour, std::chrono::milliseconds timeout);

    // ---- topics -------------------------------------------------------------------------------
    // ubii::Full when the node's subscription table (UBII_MAX_SUBSCRIPTIONS) is full;
    // ubii::Unsupported for a regex outside the supported dialect (ubii/topic.h).
    Subscription subscribe(std::string topic, RecordHandler handler);
    Subscription subscribe_regex(std::string regex, RecordHandler handler);
    // Whether subscriptions made (or cancelled) so far are still on their way to the master
    // (ubii_subscriptions_pending): poll until it is false before relying on a new subscription.
    bool subscriptions_pending() const noexcept;
    // Typed: `handler(const T &value, const ubii::RecordInfo &info)`. T may be any record member
    // type, or ubii::ImageView for images without copying the pixels. A record of another type is
    // not passed on: it is counted (Stats::type_mismatches) and reported as Status::wrong_type.
    template <class T, class Handler> Subscription subscribe(std::string topic, Handler handler)
    {
        return subscribe(std::move(topic), typed<T>(std::move(handler)));
    }
    template <class T, class Handler>
    Subscription subscribe_regex(std::string regex, Handler handler)
    {
        return subscribe_regex(std::move(regex), typed<T>(std::move(handler)));
    }

    // One record on `topic`: double, float, int32 (and narrower integers), bool, strings, any
    // message type of a member (Vector3, Pose3D, Object2DList, Image2D, Session, ...), ImageView,
    // or a ubii::Value. Throws ubii::NotConnected unless ready, ubii::WouldBlock when the transport
    // cannot take it now, ubii::TooLarge over the size limit.
    template <class T> void publish(TopicRef topic, const T &value)
    {
        throw_unless_ok(try_publish(topic, value), topic.view());
    }
    void publish(const Record &record)
    {
        throw_unless_ok(try_publish(record), record.topic());
    }
    // The same, never throwing: Status::ok or why not.
    template <class T> Status try_publish(TopicRef topic, const T &value) noexcept
    {
        using D = std::decay_t<T>;
        if constexpr (std::is_same_v<D, bool>)
            return publish_bool(topic, value);
        else if constexpr (std::is_same_v<D, double>)
            return publish_double(topic, value);
        else if constexpr (std::is_same_v<D, float>)
            return publish_float(topic, value);
        else if constexpr (std::is_integral_v<D>) {
            static_assert(sizeof(D) < sizeof(std::int32_t) ||
                              (sizeof(D) == sizeof(std::int32_t) && std::is_signed_v<D>),
                          "the schema's integer member is int32: convert explicitly");
            return publish_int32(topic, static_cast<std::int32_t>(value));
        } else if constexpr (std::is_convertible_v<const D &, std::string_view>)
            return publish_string(topic, std::string_view(value));
        else if constexpr (std::is_same_v<D, ImageView>)
            return publish_image(topic, value);
        else if constexpr (std::is_same_v<D, Value>)
            return publish_value(topic, value);
        else {
            static_assert(is_record_value_v<D>, "no TopicDataRecord member holds this type");
            return publish_message(topic, record_type_of<D>, value);
        }
    }
    Status try_publish(const Record &record) noexcept
    {
        return publish_value(record.topic(), record.value());
    }

    // ---- processing modules -------------------------------------------------------------------
    // Runs `module` on this node: on_created, its wired inputs subscribed, started. Passes run
    // inside poll(), which waits no longer than the next one is due; worker passes finish on their
    // thread and wake the poll (on the node's own Linux port; on a port of the application's, set
    // a waker with scheduler().set_waker or poll at least every millisecond while one runs).
    // What on_created throws propagates; ubii::NotFound for a wiring naming an unknown input or
    // output.
    RunningModule run(std::unique_ptr<ProcessingModule> module, const Wiring &wiring = {});
    // The node's scheduler: module timing, lockstep steps, modules added without wiring.
    Scheduler &scheduler() noexcept;

    // ---- sessions -----------------------------------------------------------------------------
    // Takes part in the sessions masters start (docs/PROTOCOL.md §5): offers `modules` at
    // registration (Client.processing_modules; dedicated:
    // NodeOptions::is_dedicated_processing_node), and when a start record assigns one of them to
    // this node's client id, makes it, keeps the master's ids, wires it by the session's IO
    // mappings (topic, topic_mux, topic_demux), starts it and reports it (runtime/add); a stop
    // record halts and destroys the session's modules, cancels their subscriptions and reports them
    // (runtime/remove). Call it before connect(): the offer goes with registrations from then on.
    // Once per node (ubii::StateError after).
    //
    // What goes wrong is an error event and a SessionEvent::failed, and the rest goes on: an
    // unknown module name or on_created throwing (that module is not run nor reported), a mapping
    // naming an input or output the module lacks (that entry is left out), the master refusing a
    // report. A start record for modules already running changes nothing. After a reconnection
    // the modules go on under the ids the master gave them (a session keeps its node ids and its
    // stop record still reaches this node); if the master itself restarted (another master id),
    // its sessions are gone and their modules are stopped.
    void serve_sessions(ModuleRegistry modules);
    void on_session_event(SessionEventHandler handler);
    // The modules this node runs for sessions now.
    std::vector<SessionModule> session_modules() const;

    // ---- external event loops -----------------------------------------------------------------
    // The file descriptors to wait on (see ubii_node_pollfds); returns how many there are, which
    // may exceed `capacity`.
    int pollfds(ubii_pollfd *fds, int capacity) noexcept;
    // How long an external loop may wait on those descriptors before calling poll(0ms): the
    // earlier of the core's next timer and the next due pass (never negative); none: until a
    // descriptor is ready.
    std::optional<std::chrono::nanoseconds> next_timeout() const;

    // ---- services -----------------------------------------------------------------------------
    // Any service: the reply as it came (an error reply resolves the call with ServiceError).
    // `timeout` 0: NodeOptions::service_timeout. ubii::NotConnected unless ready; ubii::Full when
    // the node's queue is full; ubii::TooLarge over UBII_SERVICE_QUEUE_BYTES.
    Call<ServiceReply> call(const ServiceRequest &request,
                            std::chrono::milliseconds timeout = std::chrono::milliseconds(0));
    // The same, resolved with the reply's member as a T (ubii::UnexpectedReply for another).
    template <class T>
    Call<T> call_as(const ServiceRequest &request,
                    std::chrono::milliseconds timeout = std::chrono::milliseconds(0));
    // Polls until `call` is done: its reply, or its error as an exception; ubii::Timeout if it is
    // not done within `timeout` (the call stays pending). The reply is a copy: it outlives the
    // Call, which is often a temporary (`auto topics = node.wait(node.master().topics(), 2s);`).
    template <class T> T wait(const Call<T> &call, std::chrono::milliseconds timeout)
    {
        if (!run_until([&call] { return call.done(); }, timeout))
            throw Timeout("no reply from " + call.service() + " within " +
                          std::to_string(timeout.count()) + " ms");
        return call.get();
    }
    // Typed calls of the master's services, and session control.
    Master master();
    Sessions sessions();

    // The C core's node, for the parts of the C API this layer does not cover. Callbacks set on it
    // directly bypass this layer's exception boundary.
    ubii_node *c_node() noexcept;

  private:
    template <class T, class Handler> static RecordHandler typed(Handler handler)
    {
        return [handler = std::move(handler)](const Record &record) mutable {
            if constexpr (std::is_same_v<T, ImageView>)
                handler(record.image(), record.info());
            else
                handler(record.as<T>(), record.info());
        };
    }
    void throw_unless_ok(Status status, std::string_view topic) const;
    Status publish_double(TopicRef topic, double value) noexcept;
    Status publish_float(TopicRef topic, float value) noexcept;
    Status publish_int32(TopicRef topic, std::int32_t value) noexcept;
    Status publish_bool(TopicRef topic, bool value) noexcept;
    Status publish_string(TopicRef topic, std::string_view value) noexcept;
    Status publish_image(TopicRef topic, const ImageView &image) noexcept;
    Status publish_message(TopicRef topic, RecordType type,
                           const google::protobuf::MessageLite &message) noexcept;
    Status publish_value(TopicRef topic, const Value &value) noexcept;
    // Queues `request`; `resolve` receives the reply (or the failure) inside poll().
    void queue_call(const ServiceRequest &request, std::chrono::milliseconds timeout,
                    std::function<void(Result<ServiceReply>)> resolve);

    std::shared_ptr<detail::NodeCore> core_;
};

template <class T>
Call<T> Node::call_as(const ServiceRequest &request, std::chrono::milliseconds timeout)
{
    auto state = std::make_shared<detail::CallState<T>>();
    state->service = request.topic();
    queue_call(request, timeout, [state](Result<ServiceReply> reply) {
        std::optional<Result<T>> outcome;
        if (!reply.ok()) {
            outcome.emplace(Result<T>::failure(reply.error()));
        } else {
            try {
                outcome.emplace(
                    Result<T>::success(detail::reply_member<T>(reply.value(), state->service)));
            } catch (...) {
                outcome.emplace(Result<T>::failure(std::current_exception()));
            }
        }
        // Outside the try: an exception of a continuation belongs to the application.
        state->resolve(std::move(*outcome));
    });
    return Call<T>(std::move(state));
}

} // namespace ubii

#endif
