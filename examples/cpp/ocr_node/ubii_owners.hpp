#ifndef UBII_EXAMPLE_OCR_NODE_UBII_OWNERS_HPP
#define UBII_EXAMPLE_OCR_NODE_UBII_OWNERS_HPP

// RAII owners for the C core's objects: the Linux port and a node running on it. Declare the port
// first so that it outlives the node.

#include <memory>

#include "ubii/port_linux.h"
#include "ubii/ubii.h"

namespace ocr_node
{

struct LinuxPortDeleter {
    void operator()(ubii_linux_port *port) const noexcept
    {
        ubii_linux_port_destroy(port);
    }
};
using LinuxPort = std::unique_ptr<ubii_linux_port, LinuxPortDeleter>;

// Throws std::runtime_error when libzmq or libwebsockets cannot start.
LinuxPort make_linux_port();

class Node
{
  public:
    // Throws std::runtime_error if ubii_node_init refuses `config`.
    Node(const ubii_config &config, ubii_port port);
    // Stops a node that is still running (ubii_node_stop_wait, bounded by stop_timeout_ms).
    ~Node();
    Node(const Node &) = delete;
    Node &operator=(const Node &) = delete;

    static constexpr int stop_timeout_ms = 2000;

    ubii_node *get()
    {
        return node_.get();
    }
    ubii_state state() const
    {
        return ubii_node_state(node_.get());
    }
    // ubii_node_stop_wait: UBII_OK, or UBII_ERR_TIMEOUT if the master did not confirm in time
    // (the node is closed anyway).
    ubii_status stop();

  private:
    std::unique_ptr<ubii_node> node_;
};

} // namespace ocr_node

#endif
