#ifndef UBII_CPP_SESSION_HOST_HPP
#define UBII_CPP_SESSION_HOST_HPP

// A node's part in sessions (docs/PROTOCOL.md §5): it offers the registry's modules at
// registration, runs the modules a start record assigns to its client id, wired by the session's
// IO mappings, reports them to the master, and stops them when the session stops.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ubii/messages.hpp"
#include "ubii/module_registry.hpp"
#include "ubii/processing.h"
#include "ubii/record.hpp"
#include "ubii/running_module.hpp"
#include "ubii/session_events.hpp"

namespace ubii::detail
{

class NodeCore;

class SessionHost
{
  public:
    using EventHandler = std::function<void(const SessionEvent &)>;

    explicit SessionHost(NodeCore &core);
    ~SessionHost();
    SessionHost(const SessionHost &) = delete;
    SessionHost &operator=(const SessionHost &) = delete;

    // Offers `modules` from the next registration on and subscribes the session topics.
    void serve(ModuleRegistry modules);
    bool serving() const noexcept
    {
        return serving_;
    }
    void on_event(EventHandler handler)
    {
        handler_ = std::move(handler);
    }
    std::vector<SessionModule> modules() const;
    // Ends every hosted module without telling the master (the node is going away).
    void clear() noexcept;

  private:
    struct Hosted {
        std::string name;
        std::string session_id;
        std::string node_id;
    };

    void on_start(const Record &record);
    void on_stop(const Record &record);
    void on_ready();
    void check_master(const std::string &master_id);
    // Creates, wires and starts one assigned module; false if it could not run.
    bool host(const Session &session, const ProcessingModuleSpec &assigned);
    Wiring wiring_for(const Session &session, const ProcessingModule &module);
    void stop_hosted(const std::string &id, const std::string &why) noexcept;
    ServiceRequest report_request(const char *service, const std::vector<std::string> &ids,
                                  ProcessingModuleSpec::Status status) const;
    void send_report(const ServiceRequest &request, SessionEvent::Kind confirmed);
    // Runs the application's handler; what it throws is reported, not passed on.
    void emit(SessionEvent::Kind kind, const std::string &session_id, const std::string &module_id,
              const std::string &module_name, const std::string &detail = {}) noexcept;
    // An error event and a `failed` session event.
    void fail(Status status, const std::string &session_id, const std::string &module_id,
              const std::string &module_name, const std::string &detail) noexcept;

    NodeCore &core_;
    ModuleRegistry registry_;
    std::vector<std::string> encoded_specs_;
    std::vector<ubii_encoded_message> offered_;
    bool serving_ = false;
    std::map<std::string, Hosted> hosted_; // by the module's (master-assigned) id
    // Modules that could not run, by id, with their session's id: a repeated start record does
    // not try (and report) them again; their session's stop forgets them.
    std::map<std::string, std::string> failed_;
    std::optional<std::string> master_id_;
    EventHandler handler_;
    // Calls still pending when the host is gone resolve into nothing.
    std::shared_ptr<char> alive_ = std::make_shared<char>();
};

} // namespace ubii::detail

#endif
