#include "session_host.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

#include "node_core.hpp"
#include "ubii/master.hpp"

namespace ubii
{

std::string_view to_string(SessionEvent::Kind kind) noexcept
{
    switch (kind) {
    case SessionEvent::Kind::started:
        return "started";
    case SessionEvent::Kind::confirmed_started:
        return "confirmed_started";
    case SessionEvent::Kind::confirmed_removed:
        return "confirmed_removed";
    case SessionEvent::Kind::stopped:
        return "stopped";
    case SessionEvent::Kind::failed:
        return "failed";
    }
    return "unknown";
}

namespace detail
{

namespace
{
constexpr const char session_start_topic[] = "/info/session/start";
constexpr const char session_stop_topic[] = "/info/session/stop";
constexpr const char runtime_add[] = "/services/processing_module/runtime/add";
constexpr const char runtime_remove[] = "/services/processing_module/runtime/remove";

// TopicMux/TopicDemux.data_type: the official nodes compare it with the record's member name
// ("vector3"); a message format ("ubii.dataStructure.Vector3") is taken too. NONE when empty (no
// filter), nothing when it names no member.
std::optional<RecordType> member_named(const std::string &data_type)
{
    if (data_type.empty())
        return RecordType::NONE;
    for (RecordType type : record_types) {
        if (type != RecordType::NONE && record_type_name(type) == data_type)
            return type;
    }
    const RecordType type = record_type_for_format(data_type);
    return type != RecordType::NONE ? std::optional<RecordType>(type) : std::nullopt;
}
} // namespace

SessionHost::SessionHost(NodeCore &core) : core_(core)
{
}

SessionHost::~SessionHost() = default;

void SessionHost::serve(ModuleRegistry modules)
{
    if (serving_)
        throw StateError("the node serves sessions already");
    registry_ = std::move(modules);
    for (const ProcessingModuleSpec &spec : registry_.specs())
        encoded_specs_.push_back(spec.SerializeAsString());
    for (const std::string &bytes : encoded_specs_)
        offered_.push_back({reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size()});
    const ubii_status offered =
        ubii_node_offer_processing_modules(core_.c_node(), offered_.data(), offered_.size());
    if (offered != UBII_OK)
        throw_status(to_status(offered), "cannot offer the processing modules");
    // Exact subscriptions: the master delivers its last start and stop records at once; both are
    // handled as any other (a start record for modules already running changes nothing).
    core_.subscribe(session_start_topic, false, [this](const Record &record) { on_start(record); });
    core_.subscribe(session_stop_topic, false, [this](const Record &record) { on_stop(record); });
    core_.protocol().on_enter(ConnectionState::ready,
                              [this](ConnectionTransition &) { on_ready(); });
    serving_ = true;
    if (core_.state() == ConnectionState::ready)
        on_ready();
}

std::vector<SessionModule> SessionHost::modules() const
{
    std::vector<SessionModule> modules;
    for (const auto &[id, hosted] : hosted_) {
        ProcessingStatus status = ProcessingStatus::destroyed;
        if (core_.scheduler().contains(id))
            status = core_.scheduler().module(id).status();
        modules.push_back(SessionModule{id, hosted.name, hosted.session_id, status});
    }
    return modules;
}

void SessionHost::clear() noexcept
{
    handler_ = nullptr;
    for (const auto &entry : hosted_)
        core_.remove_module(entry.first);
    hosted_.clear();
}

// After every (re)connection: a master with another id is a restarted one, and the sessions the
// node ran modules for ended with the old one (no stop record will come for them).
void SessionHost::on_ready()
{
    ServiceRequest request;
    request.set_topic(service_topics::server_configuration);
    std::weak_ptr<char> alive = alive_;
    try {
        core_.queue_call(request, std::chrono::milliseconds(0),
                         [this, alive](Result<ServiceReply> reply) {
                             if (alive.expired() || !reply.ok() || !reply.value().has_server())
                                 return;
                             check_master(reply.value().server().id());
                         });
    } catch (const Error &error) { // e.g. a full queue: the next connection checks again
        core_.report(error.status(),
                     std::string("cannot ask for the master's id: ") + error.what());
    }
}

void SessionHost::check_master(const std::string &master_id)
{
    if (master_id_ && *master_id_ != master_id && !hosted_.empty()) {
        std::vector<std::string> ids;
        for (const auto &entry : hosted_)
            ids.push_back(entry.first);
        for (const std::string &id : ids)
            stop_hosted(id, "the master restarted (its id changed): its sessions ended with it");
    }
    if (master_id_ && *master_id_ != master_id)
        failed_.clear();
    master_id_ = master_id;
}

void SessionHost::on_start(const Record &record)
{
    if (record.type() != RecordType::SESSION) {
        fail(Status::wrong_type, {}, {}, {},
             std::string(session_start_topic) + " carried a " +
                 std::string(record_type_name(record.type())) + " record, not a session");
        return;
    }
    const Session &session = record.as<Session>();
    const std::string own_id = ubii_node_client_id(core_.c_node());
    std::vector<std::string> started;
    for (const ProcessingModuleSpec &assigned : session.processing_modules()) {
        if (own_id.empty() || assigned.node_id() != own_id)
            continue;
        if (hosted_.count(assigned.id()) > 0 || failed_.count(assigned.id()) > 0)
            continue; // a repeated start record, or the master's last one on (re)subscribing
        if (host(session, assigned))
            started.push_back(assigned.id());
        else if (!assigned.id().empty())
            failed_[assigned.id()] = session.id();
    }
    if (!started.empty())
        send_report(report_request(runtime_add, started, ProcessingModuleSpec::PROCESSING),
                    SessionEvent::Kind::confirmed_started);
}

bool SessionHost::host(const Session &session, const ProcessingModuleSpec &assigned)
{
    const std::string session_id =
        assigned.session_id().empty() ? session.id() : assigned.session_id();
    if (assigned.id().empty()) {
        fail(Status::invalid_argument, session_id, {}, assigned.name(),
             "the start record gives the module no id");
        return false;
    }
    std::unique_ptr<ProcessingModule> module;
    try {
        module = registry_.create(assigned.name());
    } catch (const Error &error) {
        fail(error.status(), session_id, assigned.id(), assigned.name(), error.what());
        return false;
    } catch (const std::exception &error) {
        fail(Status::callback_threw, session_id, assigned.id(), assigned.name(),
             std::string("its factory threw: ") + error.what());
        return false;
    }
    module->id_ = assigned.id();
    module->session_id_ = session_id;
    module->node_id_ = assigned.node_id();
    const Wiring wiring = wiring_for(session, *module);
    try {
        core_.run_module(std::move(module), wiring);
    } catch (const Error &error) {
        fail(error.status(), session_id, assigned.id(), assigned.name(),
             std::string("not started: ") + error.what());
        return false;
    } catch (const std::exception &error) { // on_created's own exception
        fail(Status::callback_threw, session_id, assigned.id(), assigned.name(),
             std::string("not started: ") + error.what());
        return false;
    }
    hosted_[assigned.id()] = Hosted{assigned.name(), session_id, assigned.node_id()};
    emit(SessionEvent::Kind::started, session_id, assigned.id(), assigned.name());
    return true;
}

// The session's IO mappings bound to `module` (by its id, as the master binds them). An entry
// naming an input or output the module lacks, or a type no record member has, is reported and
// left out; the others apply.
Wiring SessionHost::wiring_for(const Session &session, const ProcessingModule &module)
{
    const ModuleDescription &description = module.description();
    Wiring wiring;
    const auto left_out = [&](const std::string &what) {
        fail(Status::not_found, module.session_id(), module.id(), module.name(),
             what + ": its mapping is left out");
    };
    const auto no_member = [](const char *io, const std::string &name, const std::string &type) {
        return std::string(io) + " \"" + name + "\": no record member is named \"" + type + "\"";
    };
    for (const IOMapping &mapping : session.io_mappings()) {
        if (mapping.processing_module_id() != module.id())
            continue;
        for (const TopicInputMapping &input : mapping.input_mappings()) {
            const std::string &name = input.input_name();
            if (find_io(description.inputs, name) == nullptr) {
                left_out("the module has no input \"" + name + "\"");
                continue;
            }
            if (input.has_topic_mux()) {
                const TopicMux &mux = input.topic_mux();
                const std::optional<RecordType> type = member_named(mux.data_type());
                if (!type) {
                    left_out(no_member("input", name, mux.data_type()));
                    continue;
                }
                if (mux.topic_selector().empty()) {
                    left_out("input \"" + name + "\": the mux has no topic selector");
                    continue;
                }
                wiring.mux_input(name, mux.topic_selector(), mux.identity_match_pattern(), *type);
            } else if (!input.topic().empty()) {
                wiring.input(name, input.topic());
            } else {
                left_out("input \"" + name + "\" is mapped to no topic");
            }
        }
        for (const TopicOutputMapping &output : mapping.output_mappings()) {
            const std::string &name = output.output_name();
            if (find_io(description.outputs, name) == nullptr) {
                left_out("the module has no output \"" + name + "\"");
                continue;
            }
            if (output.has_topic_demux()) {
                const TopicDemux &demux = output.topic_demux();
                const std::optional<RecordType> type = member_named(demux.data_type());
                if (!type) {
                    left_out(no_member("output", name, demux.data_type()));
                    continue;
                }
                wiring.demux_output(name, demux.output_topic_format(), *type);
            } else if (!output.topic().empty()) {
                wiring.output(name, output.topic());
            } else {
                left_out("output \"" + name + "\" is mapped to no topic");
            }
        }
    }
    return wiring;
}

void SessionHost::on_stop(const Record &record)
{
    if (record.type() != RecordType::SESSION)
        return;
    const std::string &session_id = record.as<Session>().id();
    for (auto it = failed_.begin(); it != failed_.end();)
        it = it->second == session_id ? failed_.erase(it) : std::next(it);
    std::vector<std::string> ids;
    for (const auto &[id, hosted] : hosted_) {
        if (hosted.session_id == session_id)
            ids.push_back(id);
    }
    if (ids.empty())
        return; // a session this node has no module in (the master tells every node)
    const ServiceRequest request =
        report_request(runtime_remove, ids, ProcessingModuleSpec::DESTROYED);
    for (const std::string &id : ids)
        stop_hosted(id, "the session stopped");
    send_report(request, SessionEvent::Kind::confirmed_removed);
}

void SessionHost::stop_hosted(const std::string &id, const std::string &why) noexcept
{
    const auto found = hosted_.find(id);
    if (found == hosted_.end())
        return;
    const Hosted hosted = found->second;
    hosted_.erase(found);
    core_.remove_module(id);
    emit(SessionEvent::Kind::stopped, hosted.session_id, id, hosted.name, why);
}

ServiceRequest SessionHost::report_request(const char *service, const std::vector<std::string> &ids,
                                           ProcessingModuleSpec::Status status) const
{
    ServiceRequest request;
    request.set_topic(service);
    for (const std::string &id : ids) {
        const Hosted &hosted = hosted_.at(id);
        ProcessingModuleSpec &spec = *request.mutable_processing_module_list()->add_elements();
        spec.set_id(id);
        spec.set_name(hosted.name);
        spec.set_node_id(hosted.node_id);
        spec.set_session_id(hosted.session_id);
        spec.set_status(status);
        spec.set_language(ProcessingModuleSpec::CPP);
    }
    return request;
}

// runtime/add and runtime/remove: only `id` and `node_id` count at the master, which verifies
// them against the session it started (docs/PROTOCOL.md §5.2). A refusal leaves the modules as
// they are (a late confirmation can still make the session RUNNING) and is reported.
void SessionHost::send_report(const ServiceRequest &request, SessionEvent::Kind confirmed)
{
    const std::vector<ProcessingModuleSpec> reported(
        request.processing_module_list().elements().begin(),
        request.processing_module_list().elements().end());
    const auto refused = [this, reported](Status status, const std::string &why) {
        for (const ProcessingModuleSpec &spec : reported)
            fail(status, spec.session_id(), spec.id(), spec.name(), why);
    };
    std::weak_ptr<char> alive = alive_;
    try {
        core_.queue_call(request, std::chrono::milliseconds(0),
                         [this, alive, reported, confirmed, refused](Result<ServiceReply> reply) {
                             if (alive.expired())
                                 return;
                             if (!reply.ok()) {
                                 refused(reply.status(), reply.error_message());
                                 return;
                             }
                             for (const ProcessingModuleSpec &spec : reported)
                                 emit(confirmed, spec.session_id(), spec.id(), spec.name());
                         });
    } catch (const Error &error) {
        refused(error.status(), request.topic() + " not sent: " + error.what());
    }
}

void SessionHost::emit(SessionEvent::Kind kind, const std::string &session_id,
                       const std::string &module_id, const std::string &module_name,
                       const std::string &detail) noexcept
{
    if (!handler_)
        return;
    try {
        handler_(SessionEvent{kind, session_id, module_id, module_name, detail});
    } catch (...) {
        core_.report_exception("a session event handler", std::current_exception());
    }
}

void SessionHost::fail(Status status, const std::string &session_id, const std::string &module_id,
                       const std::string &module_name, const std::string &detail) noexcept
{
    try {
        std::string text = "session " + (session_id.empty() ? std::string("?") : session_id);
        if (!module_name.empty() || !module_id.empty())
            text += ", processing module \"" + module_name + "\" (" + module_id + ")";
        core_.report(status, text + ": " + detail);
    } catch (...) { // building the text failed; the event below still says what it can
    }
    emit(SessionEvent::Kind::failed, session_id, module_id, module_name, detail);
}

} // namespace detail
} // namespace ubii
