#include "ubii_owners.hpp"

#include <stdexcept>
#include <string>

namespace ocr_node
{

LinuxPort make_linux_port()
{
    ubii_linux_port_options options = {};
    options.libwebsockets_log_level = 1; // errors only
    // Recognition keeps the polling thread busy for hundreds of milliseconds. libzmq's I/O thread
    // takes frames in meanwhile, so the next poll has the newest one and the stale ones are
    // dropped; the in-thread engine would leave them queued at the master, to be read in turn.
    options.zmq_engine = UBII_LINUX_ZMQ_LIBZMQ;
    ubii_linux_port *port = nullptr;
    const ubii_status status = ubii_linux_port_create(&port, &options);
    if (status != UBII_OK)
        throw std::runtime_error(std::string("cannot create the transport: ") +
                                 ubii_strerror(status));
    return LinuxPort(port);
}

Node::Node(const ubii_config &config, ubii_port port) : node_(std::make_unique<ubii_node>())
{
    const ubii_status status = ubii_node_init(node_.get(), sizeof(ubii_node), &config, port);
    if (status != UBII_OK)
        throw std::runtime_error(std::string("cannot set the node up: ") + ubii_strerror(status));
}

Node::~Node()
{
    if (state() != UBII_STATE_STOPPED)
        ubii_node_stop_wait(node_.get(), stop_timeout_ms);
}

ubii_status Node::stop()
{
    if (state() == UBII_STATE_STOPPED)
        return UBII_OK;
    return ubii_node_stop_wait(node_.get(), stop_timeout_ms);
}

} // namespace ocr_node
