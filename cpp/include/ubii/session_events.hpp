#ifndef UBII_SESSION_EVENTS_HPP
#define UBII_SESSION_EVENTS_HPP

// What a node serving sessions (Node::serve_sessions) tells the application about the processing
// modules a master assigns to it.

#include <string>
#include <string_view>

#include "ubii/processing_module.hpp"

namespace ubii
{

struct SessionEvent {
    enum class Kind {
        // Created from the registry, wired by the session's IO mappings and started.
        started,
        // The master confirmed the module started (runtime/add) or removed (runtime/remove).
        confirmed_started,
        confirmed_removed,
        // Halted and destroyed: the session stopped, or the master it ran for is gone.
        stopped,
        // Not run (unknown name, on_created threw, wiring refused), a mapping entry left out, or
        // the master refused a report; `detail` says which. Also an error event (Node::on_error).
        failed,
    };
    Kind kind;
    std::string session_id;
    std::string module_id;
    std::string module_name;
    std::string detail;
};
std::string_view to_string(SessionEvent::Kind kind) noexcept;

// A module this node runs for a session.
struct SessionModule {
    std::string id;
    std::string name;
    std::string session_id;
    ProcessingStatus status = ProcessingStatus::initialized;
};

} // namespace ubii

#endif
