#ifndef UBII_MASTER_HPP
#define UBII_MASTER_HPP

// Typed calls of the services a master offers (docs/PROTOCOL.md §2.11), through a node:
//
//     ubii::Server server = node.wait(node.master().server_configuration(), 2s);
//     auto device = node.wait(node.master().register_device(my_device), 2s);
//     auto sessions = node.wait(node.sessions().list(), 2s);
//
// Each returns a ubii::Call resolved inside poll(); the master's error reply resolves it with
// ubii::ServiceError (title and message as the master wrote them), no reply with ubii::Timeout.
// `timeout` 0: NodeOptions::service_timeout. Master and Sessions are cheap views of the node; they
// must not outlive it.

#include <chrono>
#include <string>

#include "ubii/messages.hpp"
#include "ubii/service_call.hpp"

namespace ubii
{

class Node;

// The services' topics (docs/PROTOCOL.md §2.11).
namespace service_topics
{
inline constexpr const char server_configuration[] = "/services/server_configuration";
inline constexpr const char service_list[] = "/services/service_list";
inline constexpr const char topic_list[] = "/services/topic_list";
inline constexpr const char client_list[] = "/services/client/get_list";
inline constexpr const char device_registration[] = "/services/device/registration";
inline constexpr const char device_deregistration[] = "/services/device/deregistration";
inline constexpr const char device_list[] = "/services/device/get_list";
inline constexpr const char component_list[] = "/services/component/get_list";
inline constexpr const char processing_module_list[] =
    "/services/processing_module/database/get_list";
inline constexpr const char session_start[] = "/services/session/runtime/start";
inline constexpr const char session_stop[] = "/services/session/runtime/stop";
inline constexpr const char session_get[] = "/services/session/runtime/get";
inline constexpr const char session_list[] = "/services/session/runtime/get_list";
inline constexpr const char session_save[] = "/services/session/database/save";
} // namespace service_topics

namespace detail
{
// What Master and Sessions share: the node they call through and the timeout of their calls.
class ServiceGroup
{
  protected:
    ServiceGroup(Node &node, std::chrono::milliseconds timeout) : node_(node), timeout_(timeout)
    {
    }
    template <class T> Call<T> call(ServiceRequest request);

    Node &node_;
    std::chrono::milliseconds timeout_;
};
} // namespace detail

class Master : public detail::ServiceGroup
{
  public:
    explicit Master(Node &node, std::chrono::milliseconds timeout = std::chrono::milliseconds(0))
        : ServiceGroup(node, timeout)
    {
    }
    // The same calls with another timeout.
    Master with_timeout(std::chrono::milliseconds timeout) const
    {
        return Master(node_, timeout);
    }

    Call<Server> server_configuration();
    Call<ServiceList> services();
    // Every service topic, then every topic holding data.
    Call<StringList> topics();
    // The clients the master knows (filter: the elements to match; the npm 0.4.0 master has no
    // such service and replies with an error).
    Call<ClientList> clients(const ClientList &filter = {});
    Call<DeviceList> devices(const DeviceList &filter = {});
    Call<devices::ComponentList> components(const devices::ComponentList &filter = {});
    // Registers `device` for this client (client_id is filled in); the reply carries the ids the
    // master assigned to it and its components.
    Call<Device> register_device(Device device);
    // Deregisters the device with `device_id` of this client.
    Call<Success> deregister_device(const std::string &device_id);
    // The processing module specs the master knows (its database and every client's).
    Call<ProcessingModuleSpecList> processing_modules(const ProcessingModuleSpecList &filter = {});
};

class Sessions : public detail::ServiceGroup
{
  public:
    explicit Sessions(Node &node, std::chrono::milliseconds timeout = std::chrono::milliseconds(0))
        : ServiceGroup(node, timeout)
    {
    }
    Sessions with_timeout(std::chrono::milliseconds timeout) const
    {
        return Sessions(node_, timeout);
    }

    // The sessions the master runs.
    Call<SessionList> list();
    Call<Session> get(const std::string &id);
    // Starts a session from its spec (or, by name, one the master has stored); the reply is the
    // session as the master runs it, with the id it assigned.
    Call<Session> start(Session session);
    // Stops the session with `id`, and resolves with the session as the master holds it then (the
    // current master marks it STOPPED only once every node reported its modules removed). The
    // stop's own reply says nothing: the current master answers every stop with an error, done or
    // not (docs/PROTOCOL.md §5.3), the npm 0.4.0 master one when the session was not running. So
    // the session is looked up after it: ServiceError if the master has no session `id`.
    Call<Session> stop(const std::string &id);
    // Saves a session spec in the master's database; the reply lists the sessions it created.
    Call<SessionList> save(Session session);
};

} // namespace ubii

#endif
