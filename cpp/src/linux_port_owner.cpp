#include "linux_port_owner.hpp"

#include "ubii/error.hpp"

#ifdef UBII_CPP_LINUX_PORT
#include "ubii/port_linux.h"
#endif

namespace ubii::detail
{

#ifdef UBII_CPP_LINUX_PORT

struct LinuxPortOwner::Handle {
    ubii_linux_port *port = nullptr;
    ~Handle()
    {
        if (port != nullptr)
            ubii_linux_port_destroy(port);
    }
};

LinuxPortOwner::LinuxPortOwner(const NodeOptions &options) : handle_(std::make_unique<Handle>())
{
    ubii_linux_port_options port_options = {};
    port_options.max_message_size = options.max_message_size;
    port_options.enable_tls = options.enable_tls;
    port_options.allow_self_signed = options.allow_self_signed;
    port_options.libwebsockets_log_level = options.libwebsockets_log_level;
    port_options.zmq_engine =
        options.zmq_engine == ZmqEngine::libzmq ? UBII_LINUX_ZMQ_LIBZMQ : UBII_LINUX_ZMQ_IN_THREAD;
    const ubii_status status = ubii_linux_port_create(&handle_->port, &port_options);
    if (status != UBII_OK)
        throw_status(to_status(status), "cannot create the Linux port");
    port_ = ubii_linux_port_get(handle_->port);
}

std::string LinuxPortOwner::last_error() const
{
    return ubii_linux_port_last_error(handle_->port);
}

void LinuxPortOwner::wake() noexcept
{
    ubii_linux_port_wake(handle_->port);
}

#else

struct LinuxPortOwner::Handle {
};

LinuxPortOwner::LinuxPortOwner(const NodeOptions &)
{
    throw Unsupported("this build has no Linux port: give ubii::Node a ubii_port");
}

std::string LinuxPortOwner::last_error() const
{
    return {};
}

void LinuxPortOwner::wake() noexcept
{
}

#endif

LinuxPortOwner::~LinuxPortOwner() = default;

} // namespace ubii::detail
