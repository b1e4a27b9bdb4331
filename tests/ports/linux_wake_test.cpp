// ubii_linux_port_wake: another thread ends the port's wait at once, on every path the wait takes
// (zmq_poll with no libwebsockets connection, lws_service with one, a zmq_only port), and an
// external loop sees the wake-up among the port's pollfds. The bounds are loose on purpose: a wait
// of 20 s that ends within 2 s was ended by the wake-up, not by its timeout.
#include <gtest/gtest.h>

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "loopback.h"
#include "ubii/port_linux.h"

namespace
{

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr int long_wait_ms = 20000;
constexpr auto ended_early = std::chrono::seconds(2);

struct PortDeleter {
    void operator()(ubii_linux_port *port) const
    {
        ubii_linux_port_destroy(port);
    }
};
using PortPtr = std::unique_ptr<ubii_linux_port, PortDeleter>;

PortPtr make_port(bool zmq_only)
{
    ubii_linux_port_options options{};
    options.zmq_only = zmq_only;
    options.libwebsockets_log_level = 1;
    ubii_linux_port *port = nullptr;
    EXPECT_EQ(ubii_linux_port_create(&port, &options), UBII_OK);
    return PortPtr(port);
}

// How long a wait of long_wait_ms lasts when another thread wakes the port after `delay`.
Clock::duration wait_woken_after(ubii_linux_port *port, milliseconds delay)
{
    ubii_port handle = ubii_linux_port_get(port);
    std::thread waker([port, delay] {
        std::this_thread::sleep_for(delay);
        ubii_linux_port_wake(port);
    });
    const auto start = Clock::now();
    handle.vtable->wait(handle.context, long_wait_ms);
    const auto took = Clock::now() - start;
    waker.join();
    return took;
}

// Waits until a wait of 150 ms runs to its timeout: nothing else (a connection's set-up) ends it.
bool settle(ubii_linux_port *port)
{
    ubii_port handle = ubii_linux_port_get(port);
    for (int attempt = 0; attempt < 50; ++attempt) {
        const auto start = Clock::now();
        handle.vtable->wait(handle.context, 150);
        if (Clock::now() - start >= milliseconds(120))
            return true;
    }
    return false;
}

void expect_woken_and_then_quiet(ubii_linux_port *port)
{
    ASSERT_TRUE(settle(port)) << "the port never waited quietly";
    EXPECT_LT(wait_woken_after(port, milliseconds(50)), ended_early);
    // The wake-up was consumed: the next wait runs to its timeout instead of returning at once.
    ubii_port handle = ubii_linux_port_get(port);
    const auto start = Clock::now();
    handle.vtable->wait(handle.context, 150);
    EXPECT_GE(Clock::now() - start, milliseconds(120));
}

TEST(LinuxWake, EndsAWaitWithoutConnections)
{
    PortPtr port = make_port(false);
    expect_woken_and_then_quiet(port.get());
}

TEST(LinuxWake, EndsAWaitOfAZmqOnlyPort)
{
    PortPtr port = make_port(true);
    expect_woken_and_then_quiet(port.get());
}

TEST(LinuxWake, EndsAWaitThatLibwebsocketsDrives)
{
    // A peer that accepts and never answers keeps a WebSocket connection pending in lws.
    uint16_t tcp_port = 0;
    const int listener = ubii_test::listen_on_loopback(tcp_port);
    ASSERT_GE(listener, 0);
    PortPtr port = make_port(false);
    ubii_port handle = ubii_linux_port_get(port.get());
    const std::string url = "ws://127.0.0.1:" + std::to_string(tcp_port);
    ASSERT_EQ(handle.vtable->open(handle.context, UBII_CHANNEL_TOPIC, url.c_str(), "wake-test"),
              UBII_OK);
    const int peer = accept(listener, nullptr, nullptr);
    ASSERT_GE(peer, 0);
    expect_woken_and_then_quiet(port.get());
    handle.vtable->close(handle.context, UBII_CHANNEL_TOPIC);
    close(peer);
    close(listener);
}

TEST(LinuxWake, AWakeBeforeTheWaitIsNotLost)
{
    PortPtr port = make_port(false);
    ubii_linux_port_wake(port.get());
    ubii_port handle = ubii_linux_port_get(port.get());
    const auto start = Clock::now();
    handle.vtable->wait(handle.context, long_wait_ms);
    EXPECT_LT(Clock::now() - start, ended_early);
}

TEST(LinuxWake, AnExternalLoopSeesTheWakeUpAmongThePollfds)
{
    PortPtr port = make_port(false);
    ubii_port handle = ubii_linux_port_get(port.get());
    std::vector<ubii_pollfd> fds(8);
    const int count = handle.vtable->pollfds(handle.context, fds.data(), 8);
    ASSERT_GE(count, 1);
    ASSERT_LE(count, 8);
    std::vector<pollfd> watched;
    for (int i = 0; i < count; ++i)
        watched.push_back(
            pollfd{fds[static_cast<size_t>(i)].fd, fds[static_cast<size_t>(i)].events, 0});
    EXPECT_EQ(poll(watched.data(), watched.size(), 0), 0) << "readable before any wake-up";
    std::thread waker([&port] { ubii_linux_port_wake(port.get()); });
    waker.join();
    EXPECT_EQ(poll(watched.data(), watched.size(), 5000), 1);
    // The port's own wait consumes it.
    handle.vtable->wait(handle.context, 0);
    EXPECT_EQ(poll(watched.data(), watched.size(), 0), 0);
}

} // namespace
