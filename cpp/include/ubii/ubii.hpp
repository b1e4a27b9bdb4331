#ifndef UBII_UBII_HPP
#define UBII_UBII_HPP

// The C++ layer (cpp/README.md): everything an application needs.

#include "ubii/behaviour.hpp"
#include "ubii/error.hpp"
#include "ubii/master.hpp"
#include "ubii/messages.hpp"
#include "ubii/module_arguments.hpp"
#include "ubii/module_discovery.hpp"
#include "ubii/module_registry.hpp"
#include "ubii/node.hpp"
#include "ubii/node_options.hpp"
#include "ubii/processing_module.hpp"
#include "ubii/protocol.hpp"
#include "ubii/record.hpp"
#include "ubii/record_type.hpp"
#include "ubii/result.hpp"
#include "ubii/running_module.hpp"
#include "ubii/scheduler.hpp"
#include "ubii/standalone_module.hpp"
#include "ubii/service_call.hpp"
#include "ubii/session_events.hpp"
#include "ubii/timing.hpp"
#include "ubii/value.hpp"

#endif
