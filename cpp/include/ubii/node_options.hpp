#ifndef UBII_NODE_OPTIONS_HPP
#define UBII_NODE_OPTIONS_HPP

// How a ubii::Node connects: the master's endpoints, its name, timeouts, the reconnect policy and,
// for the Linux port the node creates itself, the transport engine.
//
//     ubii::NodeOptions options;
//     options.service_url = "tcp://127.0.0.1:8101";
//     options.topic_url = "ws://127.0.0.1:8104";      // "" : ZMQ at the port the master reports
//     options.name = "my-desktop-node";
//     ubii::Node node(options);

#include <chrono>
#include <cstddef>
#include <string>

namespace ubii
{

// How the Linux port speaks tcp:// (ZMQ): ubii_linux_zmq_engine (ubii/port_linux.h).
enum class ZmqEngine {
    // libubii's own ZMTP in the polling thread: no thread, least CPU. Messages wait at the master
    // while the application does not poll.
    in_thread,
    // libzmq: its I/O thread takes messages in while the polling thread is busy (long
    // computations that should see the newest input when they come back).
    libzmq
};

// After a lost connection the node waits `first_delay`, doubling up to `max_delay`, and gives up
// (ConnectionState::failed) after `max_attempts` failures in a row (0: never).
struct ReconnectPolicy {
    std::chrono::milliseconds first_delay{250};
    std::chrono::milliseconds max_delay{8000};
    unsigned max_attempts = 0;
};

struct NodeOptions {
    // "tcp://HOST:8101" (ZMQ) or "http(s)://HOST:8102/services/binary".
    std::string service_url = "tcp://127.0.0.1:8101";
    // "tcp://HOST:8103" (ZMQ) or "ws(s)://HOST:8104"; "": ZMQ on the service URL's host at the
    // port the master reports.
    std::string topic_url;
    std::string name = "libubii-cpp";
    bool is_dedicated_processing_node = false;
    // A service call without a timeout of its own waits this long for its reply.
    std::chrono::milliseconds service_timeout{5000};
    // After the master's first PING, this long without another counts as a lost master (the npm
    // 0.4.0 master never pings). 0: no check.
    std::chrono::milliseconds ping_timeout{5000};
    // The destructor and stop_wait() wait this long for the master to confirm deregistration.
    std::chrono::milliseconds stop_timeout{2000};
    ReconnectPolicy reconnect;
    // Stamp published records with Timestamp.millis (Unix epoch ms).
    bool stamp_records = true;

    // The Linux port the node creates (ignored when the node is given a port of its own).
    ZmqEngine zmq_engine = ZmqEngine::in_thread;
    bool enable_tls = false;          // wss:// and https:// (loads OpenSSL's store: ~40 ms)
    bool allow_self_signed = false;   // TLS: accept self-signed certificates
    std::size_t max_message_size = 0; // 0: 16 MiB
    int libwebsockets_log_level = 1;  // errors only; 0 leaves libwebsockets' own setting
};

} // namespace ubii

#endif
