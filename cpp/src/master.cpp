#include "ubii/master.hpp"

#include "ubii/node.hpp"

namespace ubii
{

namespace
{
ServiceRequest request_for(const char *topic)
{
    ServiceRequest request;
    request.set_topic(topic);
    return request;
}
} // namespace

template <class T> Call<T> detail::ServiceGroup::call(ServiceRequest request)
{
    return node_.call_as<T>(request, timeout_);
}

Call<Server> Master::server_configuration()
{
    return call<Server>(request_for(service_topics::server_configuration));
}

Call<ServiceList> Master::services()
{
    return call<ServiceList>(request_for(service_topics::service_list));
}

Call<StringList> Master::topics()
{
    return call<StringList>(request_for(service_topics::topic_list));
}

// A filter is sent only when it has elements: the master treats a present, empty list as a filter
// that matches nothing on some services.
Call<ClientList> Master::clients(const ClientList &filter)
{
    ServiceRequest request = request_for(service_topics::client_list);
    if (filter.elements_size() > 0)
        *request.mutable_client_list() = filter;
    return call<ClientList>(std::move(request));
}

Call<DeviceList> Master::devices(const DeviceList &filter)
{
    ServiceRequest request = request_for(service_topics::device_list);
    if (filter.elements_size() > 0)
        *request.mutable_device_list() = filter;
    return call<DeviceList>(std::move(request));
}

Call<devices::ComponentList> Master::components(const devices::ComponentList &filter)
{
    ServiceRequest request = request_for(service_topics::component_list);
    if (filter.elements_size() > 0)
        *request.mutable_component_list() = filter;
    return call<devices::ComponentList>(std::move(request));
}

Call<Device> Master::register_device(Device device)
{
    device.set_client_id(node_.client_id());
    ServiceRequest request = request_for(service_topics::device_registration);
    *request.mutable_device() = std::move(device);
    return call<Device>(std::move(request));
}

Call<Success> Master::deregister_device(const std::string &device_id)
{
    ServiceRequest request = request_for(service_topics::device_deregistration);
    request.mutable_device()->set_id(device_id);
    request.mutable_device()->set_client_id(node_.client_id());
    return call<Success>(std::move(request));
}

Call<ProcessingModuleSpecList> Master::processing_modules(const ProcessingModuleSpecList &filter)
{
    ServiceRequest request = request_for(service_topics::processing_module_list);
    if (filter.elements_size() > 0)
        *request.mutable_processing_module_list() = filter;
    return call<ProcessingModuleSpecList>(std::move(request));
}

Call<SessionList> Sessions::list()
{
    return call<SessionList>(request_for(service_topics::session_list));
}

Call<Session> Sessions::get(const std::string &id)
{
    ServiceRequest request = request_for(service_topics::session_get);
    request.mutable_session()->set_id(id);
    return call<Session>(std::move(request));
}

Call<Session> Sessions::start(Session session)
{
    ServiceRequest request = request_for(service_topics::session_start);
    *request.mutable_session() = std::move(session);
    return call<Session>(std::move(request));
}

Call<Session> Sessions::stop(const std::string &id)
{
    ServiceRequest request = request_for(service_topics::session_stop);
    request.mutable_session()->set_id(id);
    auto state = std::make_shared<detail::CallState<Session>>();
    state->service = service_topics::session_stop;
    Sessions lookup = *this;
    call<ServiceReply>(std::move(request))
        .then([state, lookup, id](const Result<ServiceReply> &stopped) mutable {
            if (!stopped.ok() && stopped.status() != Status::broker) { // no answer at all
                state->resolve(Result<Session>::failure(stopped.error()));
                return;
            }
            lookup.get(id).then(
                [state](const Result<Session> &session) { state->resolve(session); });
        });
    return Call<Session>(std::move(state));
}

Call<SessionList> Sessions::save(Session session)
{
    ServiceRequest request = request_for(service_topics::session_save);
    *request.mutable_session() = std::move(session);
    return call<SessionList>(std::move(request));
}

} // namespace ubii
