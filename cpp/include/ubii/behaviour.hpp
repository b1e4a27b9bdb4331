#ifndef UBII_BEHAVIOUR_HPP
#define UBII_BEHAVIOUR_HPP

// Behaviours (thesis §2.3.1): what a node does for the application, each usable from some point of
// the connection lifecycle on. A node says which it implements and whether one is usable now, and
// runs code once it becomes usable (Node::implements, Node::usable, Node::when_usable).
//
//   subscriptions       local subscriptions can be made at any time; usable once the master
//                       forwards records (the node is ready)
//   publishing          records reach the master: ready
//   services            service calls go out: ready
//   devices             device registration (a service): ready
//   processing_modules  running the processing modules sessions assign to the node: usable once
//                       the node serves sessions (Node::serve_sessions) and is ready

#include <string_view>

namespace ubii
{

enum class Behaviour { subscriptions, publishing, services, devices, processing_modules };

std::string_view to_string(Behaviour behaviour) noexcept;

} // namespace ubii

#endif
