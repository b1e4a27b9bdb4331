#include "fault_proxy.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <deque>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace ubii_test
{
namespace
{

using Clock = std::chrono::steady_clock;

struct Chunk {
    std::vector<uint8_t> bytes;
    Clock::time_point due;
};

struct Connection {
    int node = -1;
    int master = -1;
    std::deque<Chunk> to_master;
    std::deque<Chunk> to_node;
    bool close_after_to_node = false; // a truncated chunk is the last one
};

sockaddr_in loopback(uint16_t port)
{
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return address;
}

void close_connection(Connection &connection)
{
    if (connection.node >= 0)
        ::close(connection.node);
    if (connection.master >= 0)
        ::close(connection.master);
    connection.node = connection.master = -1;
}

bool send_all(int fd, const uint8_t *bytes, size_t size)
{
    while (size > 0) {
        ssize_t sent = ::send(fd, bytes, size, MSG_NOSIGNAL);
        if (sent <= 0)
            return false;
        bytes += sent;
        size -= static_cast<size_t>(sent);
    }
    return true;
}

} // namespace

struct FaultProxy::Impl {
    int listener = -1;
    std::vector<Connection> connections;

    std::mutex mutex; // guards the commands below, set by the test's thread
    bool stalled = false;
    std::chrono::milliseconds delay{0};
    bool cut = false;
    bool truncate_next = false;
    bool corrupt_next = false;
    bool pinging = false;
    FaultProxy::Framing ping_framing = FaultProxy::Framing::zmtp;
    std::chrono::milliseconds ping_every{0};
    Clock::time_point next_ping;
};

FaultProxy::FaultProxy(uint16_t listen_port, uint16_t upstream_port)
    : listen_port_(listen_port), upstream_port_(upstream_port), impl_(std::make_unique<Impl>())
{
    impl_->listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    int yes = 1;
    ::setsockopt(impl_->listener, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in address = loopback(listen_port);
    if (impl_->listener < 0 ||
        ::bind(impl_->listener, reinterpret_cast<sockaddr *>(&address), sizeof address) != 0 ||
        ::listen(impl_->listener, 8) != 0) {
        if (impl_->listener >= 0)
            ::close(impl_->listener);
        throw std::runtime_error("fault proxy: cannot listen on port " +
                                 std::to_string(listen_port));
    }
    thread_ = std::thread([this] { run(); });
}

FaultProxy::~FaultProxy()
{
    stopping_ = true;
    thread_.join();
    for (auto &connection : impl_->connections)
        close_connection(connection);
    ::close(impl_->listener);
}

void FaultProxy::pass()
{
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->stalled = false;
    impl_->delay = std::chrono::milliseconds(0);
}

void FaultProxy::delay(std::chrono::milliseconds by)
{
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->delay = by;
}

void FaultProxy::stall()
{
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->stalled = true;
}

void FaultProxy::cut()
{
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->cut = true;
}

void FaultProxy::truncate_next_from_master()
{
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->truncate_next = true;
}

void FaultProxy::corrupt_next_from_master()
{
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->corrupt_next = true;
}

void FaultProxy::send_pings(Framing protocol, std::chrono::milliseconds every)
{
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->pinging = true;
    impl_->ping_framing = protocol;
    impl_->ping_every = every;
    impl_->next_ping = Clock::now();
}

void FaultProxy::run()
{
    auto &connections = impl_->connections;
    while (!stopping_) {
        bool stalled;
        std::chrono::milliseconds delay;
        {
            std::lock_guard<std::mutex> lock(impl_->mutex);
            if (impl_->cut) {
                for (auto &connection : connections)
                    close_connection(connection);
                impl_->cut = false;
            }
            stalled = impl_->stalled;
            delay = impl_->delay;
        }
        connections.erase(std::remove_if(connections.begin(), connections.end(),
                                         [](const Connection &c) { return c.node < 0; }),
                          connections.end());

        std::vector<pollfd> fds{{impl_->listener, POLLIN, 0}};
        for (const auto &connection : connections) {
            short events = stalled ? 0 : POLLIN;
            fds.push_back({connection.node, events, 0});
            fds.push_back({connection.master, events, 0});
        }
        if (::poll(fds.data(), fds.size(), 5) < 0)
            continue;

        const auto now = Clock::now();
        {
            // The master's keep-alive: ZMTP [empty delimiter, "PING"] as its ROUTER sends it, or
            // an unmasked WebSocket text frame "PING".
            static const uint8_t zmtp_ping[] = {0x01, 0x00, 0x00, 0x04, 'P', 'I', 'N', 'G'};
            static const uint8_t websocket_ping[] = {0x81, 0x04, 'P', 'I', 'N', 'G'};
            std::lock_guard<std::mutex> lock(impl_->mutex);
            if (impl_->pinging && !stalled && now >= impl_->next_ping) {
                impl_->next_ping = now + impl_->ping_every;
                const bool zmtp = impl_->ping_framing == Framing::zmtp;
                for (auto &connection : connections) {
                    if (zmtp)
                        connection.to_node.push_back(
                            {{std::begin(zmtp_ping), std::end(zmtp_ping)}, now});
                    else
                        connection.to_node.push_back(
                            {{std::begin(websocket_ping), std::end(websocket_ping)}, now});
                }
            }
        }
        const size_t polled = connections.size(); // a connection accepted below has no pollfd yet
        for (size_t i = 0; i < polled && !stalled; ++i) {
            Connection &connection = connections[i];
            const pollfd &from_node = fds[1 + 2 * i];
            const pollfd &from_master = fds[2 + 2 * i];
            uint8_t buffer[64 * 1024];
            if (connection.node >= 0 && (from_node.revents & (POLLIN | POLLHUP | POLLERR))) {
                ssize_t got = ::recv(connection.node, buffer, sizeof buffer, 0);
                if (got <= 0) {
                    close_connection(connection);
                    continue;
                }
                connection.to_master.push_back({{buffer, buffer + got}, now + delay});
            }
            if (connection.master >= 0 && (from_master.revents & (POLLIN | POLLHUP | POLLERR))) {
                ssize_t got = ::recv(connection.master, buffer, sizeof buffer, 0);
                if (got <= 0) {
                    close_connection(connection);
                    continue;
                }
                Chunk chunk{{buffer, buffer + got}, now + delay};
                std::lock_guard<std::mutex> lock(impl_->mutex);
                if (impl_->truncate_next) {
                    chunk.bytes.resize(chunk.bytes.size() / 2);
                    connection.close_after_to_node = true;
                    impl_->truncate_next = false;
                } else if (impl_->corrupt_next) {
                    for (auto &byte : chunk.bytes)
                        byte = static_cast<uint8_t>(~byte);
                    impl_->corrupt_next = false;
                }
                connection.to_node.push_back(std::move(chunk));
            }
            while (connection.node >= 0 && !connection.to_master.empty() &&
                   connection.to_master.front().due <= now) {
                const auto &bytes = connection.to_master.front().bytes;
                if (!send_all(connection.master, bytes.data(), bytes.size()))
                    close_connection(connection);
                else
                    connection.to_master.pop_front();
            }
            while (connection.node >= 0 && !connection.to_node.empty() &&
                   connection.to_node.front().due <= now) {
                const auto &bytes = connection.to_node.front().bytes;
                bool sent = send_all(connection.node, bytes.data(), bytes.size());
                connection.to_node.pop_front();
                if (!sent || (connection.to_node.empty() && connection.close_after_to_node))
                    close_connection(connection);
            }
        }
        if (fds[0].revents & POLLIN) {
            int node = ::accept4(impl_->listener, nullptr, nullptr, SOCK_CLOEXEC);
            int master = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
            sockaddr_in address = loopback(upstream_port_);
            if (node >= 0 && master >= 0 &&
                ::connect(master, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0) {
                Connection connection;
                connection.node = node;
                connection.master = master;
                connections.push_back(std::move(connection));
                accepted_++;
            } else {
                if (node >= 0)
                    ::close(node);
                if (master >= 0)
                    ::close(master);
            }
        }
    }
}

} // namespace ubii_test
