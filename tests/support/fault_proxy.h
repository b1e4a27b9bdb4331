#ifndef UBII_TEST_FAULT_PROXY_H
#define UBII_TEST_FAULT_PROXY_H

// A TCP proxy between a node and the master that misbehaves on request: it forwards every
// connection it accepts on 127.0.0.1:listen_port to 127.0.0.1:upstream_port, and the test tells it
// to delay, stall, cut, truncate or corrupt. It runs on a thread of its own; every method may be
// called from the test's thread at any time.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <thread>

namespace ubii_test
{

class FaultProxy
{
  public:
    FaultProxy(uint16_t listen_port, uint16_t upstream_port);
    ~FaultProxy();
    FaultProxy(const FaultProxy &) = delete;
    FaultProxy &operator=(const FaultProxy &) = delete;

    uint16_t port() const
    {
        return listen_port_;
    }

    // Forwards everything at once again (ends stall and delay).
    void pass();
    // Holds every chunk this long before forwarding it, in order.
    void delay(std::chrono::milliseconds by);
    // Stops forwarding in both directions but keeps every socket open: a half-open connection
    // as neither side can tell from the socket.
    void stall();
    // Closes every connection now (new ones are accepted and forwarded).
    void cut();
    // Forwards half of the next chunk from the master, then closes that connection: a frame cut
    // off in the middle.
    void truncate_next_from_master();
    // Inverts every byte of the next chunk from the master, then forwards it.
    void corrupt_next_from_master();

    // Plays a master that keeps the connection alive (the npm master never does): every `every`,
    // while not stalled, a PING goes to each connection as `protocol` frames it. Only on an idle,
    // open connection: a PING dropped into the middle of a frame would break the stream.
    enum class Framing { zmtp, websocket };
    void send_pings(Framing protocol, std::chrono::milliseconds every);

    // Connections accepted so far (a reconnecting node makes a new one).
    int accepted() const
    {
        return accepted_.load();
    }

  private:
    struct Impl;
    void run();

    uint16_t listen_port_;
    uint16_t upstream_port_;
    std::atomic<bool> stopping_{false};
    std::atomic<int> accepted_{0};
    std::unique_ptr<Impl> impl_;
    std::thread thread_;
};

} // namespace ubii_test

#endif
