#ifndef UBII_CPP_NODE_CORE_HPP
#define UBII_CPP_NODE_CORE_HPP

// What a ubii::Node owns: the C node, its port, the handlers the C callbacks lead to, and the
// connection protocol. Shared with Subscription handles (weakly), so that a handle outliving its
// node is harmless. Every C callback enters here, and no exception leaves.

#include <cstdint>
#include <functional>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "linux_port_owner.hpp"
#include "session_host.hpp"
#include "ubii/node.hpp"
#include "ubii/running_module.hpp"
#include "ubii/scheduler.hpp"
#include "ubii/ubii.h"

namespace ubii::detail
{

class NodeCore
{
  public:
    NodeCore(NodeOptions options, const ubii_port *port);
    ~NodeCore();
    NodeCore(const NodeCore &) = delete;
    NodeCore &operator=(const NodeCore &) = delete;

    struct Handler {
        NodeCore *core;
        std::uint64_t id;
        Node::RecordHandler fn;
        ubii_subscription c_handle = 0;
        bool active = true;
        std::string pattern;
    };
    struct PendingCall {
        NodeCore *core;
        std::string service;
        std::chrono::milliseconds timeout;
        std::function<void(Result<ServiceReply>)> resolve;
    };

    void start();
    void poll(std::chrono::milliseconds timeout);
    bool stop_wait(std::chrono::milliseconds timeout);
    ConnectionState state() const noexcept
    {
        return protocol_.state();
    }
    ubii_node *c_node() noexcept
    {
        return node_.get();
    }
    std::string transport_error() const;

    std::uint64_t subscribe(std::string pattern, bool regex, Node::RecordHandler fn);
    void unsubscribe(std::uint64_t id) noexcept;
    bool subscribed(std::uint64_t id) const noexcept;

    std::string &encode_buffer() noexcept
    {
        return encode_buffer_;
    }
    void queue_call(const ServiceRequest &request, std::chrono::milliseconds timeout,
                    std::function<void(Result<ServiceReply>)> resolve);

    void when_usable(Behaviour behaviour, std::function<void()> action);

    Scheduler &scheduler() noexcept
    {
        return *scheduler_;
    }
    // Adds `module` to the scheduler, subscribes its wired inputs and starts it; what fails
    // undoes the rest and propagates.
    std::string run_module(std::unique_ptr<ProcessingModule> module, const Wiring &wiring);
    // Cancels the module's subscriptions and destroys it; no effect for an unknown id.
    void remove_module(const std::string &id) noexcept;
    // How long poll() may wait before a pass is due (none: nothing is due).
    std::optional<std::chrono::nanoseconds> until_due() const;
    bool usable(Behaviour behaviour) const noexcept;

    ConnectionProtocol &protocol() noexcept
    {
        return protocol_;
    }
    const NodeOptions &options() const noexcept
    {
        return options_;
    }
    void set_state_handler(Node::StateHandler handler)
    {
        state_handler_ = std::move(handler);
    }
    void set_error_handler(Node::ErrorHandler handler)
    {
        error_handler_ = std::move(handler);
    }
    Stats stats() const noexcept;

    // Runs the application's `code`; an exception becomes an error event naming where it came
    // from: `where` is a string, or a callable making one (only when something was thrown, so
    // that the per-record path builds no string).
    template <class Where, class F> void guard(const Where &where, F &&code) noexcept;
    void report(Status status, const std::string &detail) noexcept;
    void report_exception(const std::string &where, std::exception_ptr error) noexcept;

    // The node's part in sessions, made when first asked for.
    SessionHost &session_host();
    const SessionHost *session_host_if_any() const noexcept
    {
        return session_host_.get();
    }

  private:
    static void on_state(ubii_node *, ubii_state previous, ubii_state current, ubii_status reason,
                         void *user);
    static void on_error(ubii_node *, ubii_status status, const char *detail, void *user);
    static void on_record(ubii_node *, const ubii_record *record, void *user);
    static void on_reply(ubii_node *, const ubii_reply *reply, void *user);
    void mirror(ubii_state current, ubii_status reason);
    void settle();
    void after_poll();
    void wait_for_io(std::chrono::milliseconds timeout);
    // Throws ubii::Error subclasses for an output its wiring cannot take (the scheduler reports
    // them with the module's name).
    Status publish_output(const ProcessingModule &module, const PassOutput &output);

    struct ModuleWiring {
        std::vector<std::uint64_t> subscriptions;
        std::map<std::string, Wiring::Output, std::less<>> outputs;
    };

    NodeOptions options_;
    std::unique_ptr<LinuxPortOwner> owned_port_;
    ubii_port port_{};
    std::unique_ptr<ubii_node> node_;
    ConnectionProtocol protocol_;
    Status last_reason_ = Status::ok;
    Node::StateHandler state_handler_;
    Node::ErrorHandler error_handler_;
    std::map<std::uint64_t, std::unique_ptr<Handler>> handlers_;
    std::vector<std::unique_ptr<Handler>> retired_; // cancelled while their callback may run
    std::uint64_t next_handler_id_ = 0;
    std::map<const PendingCall *, std::unique_ptr<PendingCall>> calls_;
    std::vector<std::pair<Behaviour, std::function<void()>>> waiting_;
    std::string encode_buffer_;
    std::map<std::string, ModuleWiring, std::less<>> module_wirings_;
    // Destroyed first (~NodeCore): modules end while the node they publish on still stands.
    std::unique_ptr<Scheduler> scheduler_;
    std::unique_ptr<SessionHost> session_host_;
    std::uint64_t callback_errors_ = 0;
    std::uint64_t type_mismatches_ = 0;
    int poll_depth_ = 0;
    bool destroying_ = false;
};

} // namespace ubii::detail

#endif
