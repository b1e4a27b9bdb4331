// The Linux port's in-thread ZMQ engine (UBII_LINUX_ZMQ_IN_THREAD, the default) against a
// hand-written ZMTP peer on loopback: what goes over the wire, and what the port does with bytes
// the master would never send. Everything runs in the test's thread: the peer is served between the
// port's waits.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <dirent.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "loopback.h"
#include "ubii/port_linux.h"

namespace
{

using Bytes = std::vector<uint8_t>;

Bytes frame(const std::string &body, bool more)
{
    Bytes bytes;
    if (body.size() > 255) {
        bytes.push_back(static_cast<uint8_t>(0x02 | (more ? 1 : 0)));
        for (int shift = 56; shift >= 0; shift -= 8) {
            bytes.push_back(static_cast<uint8_t>(static_cast<uint64_t>(body.size()) >> shift));
        }
    } else {
        bytes.push_back(more ? 1 : 0);
        bytes.push_back(static_cast<uint8_t>(body.size()));
    }
    bytes.insert(bytes.end(), body.begin(), body.end());
    return bytes;
}

// What a ROUTER sends a DEALER: the empty delimiter, then the payload.
Bytes routed(const std::string &payload)
{
    Bytes bytes = frame("", true);
    Bytes rest = frame(payload, false);
    bytes.insert(bytes.end(), rest.begin(), rest.end());
    return bytes;
}

Bytes peer_handshake(const char *socket_type)
{
    Bytes bytes(64, 0);
    bytes[0] = 0xFF;
    bytes[9] = 0x7F;
    bytes[10] = 3;
    std::memcpy(bytes.data() + 12, "NULL", 4);
    std::string ready = std::string("\5READY") + "\13Socket-Type" + std::string(3, '\0') +
                        static_cast<char>(std::strlen(socket_type)) + socket_type;
    Bytes command = {0x04, static_cast<uint8_t>(ready.size())};
    command.insert(command.end(), ready.begin(), ready.end());
    bytes.insert(bytes.end(), command.begin(), command.end());
    return bytes;
}

// A loopback listener that accepts one client; the test serves it between the port's waits.
class Peer
{
  public:
    Peer()
    {
        listener_ = ubii_test::listen_on_loopback(port_);
        if (listener_ < 0) {
            ADD_FAILURE() << "cannot listen on loopback";
        }
    }
    ~Peer()
    {
        if (client_ >= 0) {
            close(client_);
        }
        close(listener_);
    }
    std::string url() const
    {
        return "tcp://127.0.0.1:" + std::to_string(port_);
    }

    // Accepts if a client is waiting, and reads what it has sent.
    void serve()
    {
        pollfd fd{client_ >= 0 ? client_ : listener_, POLLIN, 0};
        if (poll(&fd, 1, 0) <= 0) {
            return;
        }
        if (client_ < 0) {
            client_ = accept(listener_, nullptr, nullptr);
            return;
        }
        uint8_t buffer[65536];
        ssize_t got = recv(client_, buffer, sizeof buffer, MSG_DONTWAIT);
        if (got > 0) {
            received.insert(received.end(), buffer, buffer + got);
        }
    }
    bool connected() const
    {
        return client_ >= 0;
    }
    void drop_client()
    {
        close(client_);
        client_ = -1;
    }
    void send_bytes(const Bytes &bytes)
    {
        ASSERT_EQ(send(client_, bytes.data(), bytes.size(), 0), static_cast<ssize_t>(bytes.size()));
    }
    // Sends what the socket takes now of at most `size` bytes; returns how many went.
    size_t send_some(const uint8_t *data, size_t size)
    {
        ssize_t sent = send(client_, data, size, MSG_DONTWAIT | MSG_NOSIGNAL);
        return sent > 0 ? static_cast<size_t>(sent) : 0;
    }

    Bytes received;

  private:
    int listener_ = -1;
    int client_ = -1;
    uint16_t port_ = 0;
};

// Waits on the port and serves the peer between its waits until `done`, at most `limit`. `done`
// may take what it looks at (received messages): it is asked once per round.
bool pump_until(const ubii_port &port, Peer &peer, const std::function<bool()> &done,
                std::chrono::milliseconds limit = std::chrono::seconds(2), int wait_ms = 5)
{
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (!done()) {
        if (std::chrono::steady_clock::now() > deadline) {
            return false;
        }
        port.vtable->wait(port.context, wait_ms);
        peer.serve();
    }
    return true;
}

// Opens the topic channel to the peer as client-7 and plays the master's half of the handshake
// until the channel is OPEN.
void open_topic(const ubii_port &port, Peer &peer)
{
    ASSERT_EQ(port.vtable->open(port.context, UBII_CHANNEL_TOPIC, peer.url().c_str(), "client-7"),
              UBII_OK);
    ASSERT_TRUE(
        pump_until(port, peer, [&] { return peer.connected() && peer.received.size() >= 64; }));
    peer.send_bytes(peer_handshake("ROUTER"));
    ASSERT_TRUE(pump_until(port, peer, [&] {
        return port.vtable->state(port.context, UBII_CHANNEL_TOPIC) == UBII_CHANNEL_OPEN;
    }));
}

class InThreadZmtp : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        ubii_linux_port_options options{};
        options.libwebsockets_log_level = 1;
        options.zmq_engine = UBII_LINUX_ZMQ_IN_THREAD;
        options.max_message_size = 1024;
        ASSERT_EQ(ubii_linux_port_create(&linux_port_, &options), UBII_OK);
        port_ = ubii_linux_port_get(linux_port_);
    }
    void TearDown() override
    {
        ubii_linux_port_destroy(linux_port_);
    }

    ubii_channel_state state(ubii_channel channel)
    {
        return port_.vtable->state(port_.context, channel);
    }
    // Waits and serves the peer until `done`, at most two seconds.
    bool pump_until(const std::function<bool()> &done)
    {
        return ::pump_until(port_, peer_, done);
    }
    void open_topic()
    {
        ::open_topic(port_, peer_);
    }
    std::vector<std::string> take_all(ubii_channel channel)
    {
        std::vector<std::string> messages;
        const uint8_t *data;
        size_t size;
        unsigned flags;
        while (port_.vtable->receive(port_.context, channel, &data, &size, &flags) == UBII_OK) {
            messages.emplace_back(reinterpret_cast<const char *>(data), size);
        }
        return messages;
    }
    void send_message(ubii_channel channel, const std::string &payload)
    {
        uint8_t *buffer = nullptr;
        ASSERT_EQ(port_.vtable->send_begin(port_.context, channel, payload.size(), &buffer),
                  UBII_OK);
        std::memcpy(buffer, payload.data(), payload.size());
        ASSERT_EQ(port_.vtable->send_commit(port_.context, channel, 0), UBII_OK);
    }

    ubii_linux_port *linux_port_ = nullptr;
    ubii_port port_{};
    Peer peer_;
};

TEST_F(InThreadZmtp, DealerAnnouncesItsIdentityAndExchangesMessagesWithoutDelimiters)
{
    open_topic();
    std::string said(peer_.received.begin() + 64, peer_.received.end());
    EXPECT_NE(said.find("Socket-Type"), std::string::npos);
    EXPECT_NE(said.find("DEALER"), std::string::npos);
    EXPECT_NE(said.find(std::string("Identity") + std::string(3, '\0') + "\10client-7"),
              std::string::npos);

    // Three messages in one write, one of them long-framed, come out whole and in order.
    Bytes burst = routed("first");
    for (const std::string &payload : {std::string(300, 'x'), std::string("third")}) {
        Bytes more = routed(payload);
        burst.insert(burst.end(), more.begin(), more.end());
    }
    peer_.send_bytes(burst);
    std::vector<std::string> got;
    ASSERT_TRUE(pump_until([&] {
        for (std::string &message : take_all(UBII_CHANNEL_TOPIC)) {
            got.push_back(message);
        }
        return got.size() >= 3;
    }));
    EXPECT_EQ(got, (std::vector<std::string>{"first", std::string(300, 'x'), "third"}));

    // What the DEALER sends is one frame per message: the master reads no delimiter there.
    size_t handshake = peer_.received.size();
    send_message(UBII_CHANNEL_TOPIC, "up");
    send_message(UBII_CHANNEL_TOPIC, std::string(256, 'y'));
    Bytes expected = frame("up", false);
    Bytes long_one = frame(std::string(256, 'y'), false);
    expected.insert(expected.end(), long_one.begin(), long_one.end());
    ASSERT_TRUE(pump_until([&] { return peer_.received.size() >= handshake + expected.size(); }));
    EXPECT_EQ(Bytes(peer_.received.begin() + static_cast<long>(handshake), peer_.received.end()),
              expected);
}

TEST_F(InThreadZmtp, RequestCarriesTheEmptyDelimiterAndTheReplyLosesIt)
{
    ASSERT_EQ(port_.vtable->open(port_.context, UBII_CHANNEL_SERVICE, peer_.url().c_str(), ""),
              UBII_OK);
    send_message(UBII_CHANNEL_SERVICE, "request"); // waits for the master's READY
    ASSERT_TRUE(pump_until([&] { return peer_.connected() && peer_.received.size() >= 64; }));
    peer_.send_bytes(peer_handshake("REP"));
    Bytes expected = frame("", true);
    Bytes body = frame("request", false);
    expected.insert(expected.end(), body.begin(), body.end());
    ASSERT_TRUE(pump_until([&] {
        std::string text(peer_.received.begin(), peer_.received.end());
        return text.find("request") != std::string::npos;
    }));
    std::string said(peer_.received.begin() + 64, peer_.received.end());
    EXPECT_NE(said.find("REQ"), std::string::npos);
    EXPECT_EQ(said.find("Identity"), std::string::npos);
    EXPECT_EQ(
        Bytes(peer_.received.end() - static_cast<long>(expected.size()), peer_.received.end()),
        expected);

    peer_.send_bytes(routed("reply"));
    std::vector<std::string> got;
    ASSERT_TRUE(pump_until([&] {
        got = take_all(UBII_CHANNEL_SERVICE);
        return !got.empty();
    }));
    EXPECT_EQ(got, std::vector<std::string>{"reply"});
}

// The engine's buffers under every pattern of arrival: messages from empty to over a megabyte,
// cut into slices of one byte to many kilobytes, taken while more arrive (the buffer is moved,
// grown and given back), while the port sends messages of its own the other way. Every message
// arrives whole and in order.
TEST(InThreadZmtpStream, MessagesOfEverySizeInAnySlicesArriveWholeAndInOrder)
{
    Peer peer;
    ubii_linux_port_options options{};
    options.max_message_size = 2 * 1024 * 1024;
    ubii_linux_port *linux_port = nullptr;
    ASSERT_EQ(ubii_linux_port_create(&linux_port, &options), UBII_OK);
    ubii_port port = ubii_linux_port_get(linux_port);
    open_topic(port, peer);
    if (HasFatalFailure()) {
        ubii_linux_port_destroy(linux_port);
        return;
    }
    auto pump = [&](const std::function<bool()> &done) {
        return pump_until(port, peer, done, std::chrono::seconds(20), 1);
    };

    std::mt19937 random(7);
    std::vector<std::string> sent;
    Bytes stream;
    for (int i = 0; i < 300; ++i) {
        const size_t sizes[] = {0, 1, 255, 256, 4096, 70000, 300000, 1500000};
        size_t size = sizes[random() % (i % 50 == 49 ? 8 : 6)] + random() % 3;
        std::string payload(size, '\0');
        for (char &c : payload) {
            c = static_cast<char>(random());
        }
        Bytes framed = routed(payload);
        stream.insert(stream.end(), framed.begin(), framed.end());
        sent.push_back(std::move(payload));
    }
    std::vector<std::string> got;
    size_t at = 0;
    size_t replies = 0;
    ASSERT_TRUE(pump([&] {
        const size_t slices[] = {1, 7, 100, 4096, 65536, 1 << 20};
        at +=
            peer.send_some(stream.data() + at, std::min(stream.size() - at, slices[random() % 6]));
        const uint8_t *data;
        size_t size;
        unsigned flags;
        // Now all that has arrived, now some of it: the rest stays in the engine's buffer.
        for (int taken = 0, most = static_cast<int>(random() % 4);
             (most == 0 || taken < most) && port.vtable->receive(port.context, UBII_CHANNEL_TOPIC,
                                                                 &data, &size, &flags) == UBII_OK;
             ++taken) {
            got.emplace_back(reinterpret_cast<const char *>(data), size);
        }
        uint8_t *buffer = nullptr;
        if (replies < got.size() &&
            port.vtable->send_begin(port.context, UBII_CHANNEL_TOPIC, 3, &buffer) == UBII_OK) {
            std::memcpy(buffer, "ack", 3);
            port.vtable->send_commit(port.context, UBII_CHANNEL_TOPIC, 0);
            ++replies;
        }
        return (got.size() == sent.size() && at == stream.size()) ||
               port.vtable->state(port.context, UBII_CHANNEL_TOPIC) == UBII_CHANNEL_LOST;
    })) << got.size()
        << " of " << sent.size() << " arrived";
    ASSERT_EQ(port.vtable->state(port.context, UBII_CHANNEL_TOPIC), UBII_CHANNEL_OPEN)
        << got.size() << " of " << sent.size() << " arrived; "
        << ubii_linux_port_last_error(linux_port);
    ASSERT_EQ(got.size(), sent.size());
    for (size_t i = 0; i < sent.size(); ++i) {
        ASSERT_EQ(got[i].size(), sent[i].size()) << "message " << i;
        ASSERT_TRUE(got[i] == sent[i]) << "message " << i;
    }
    // The port's own messages went out whole the other way.
    Bytes acks;
    for (size_t i = 0; i < replies; ++i) {
        Bytes ack = frame("ack", false);
        acks.insert(acks.end(), ack.begin(), ack.end());
    }
    ASSERT_GT(replies, 0u);
    EXPECT_TRUE(pump([&] {
        return peer.received.size() >= acks.size() &&
               Bytes(peer.received.end() - static_cast<long>(acks.size()), peer.received.end()) ==
                   acks;
    }));
    EXPECT_EQ(port.vtable->state(port.context, UBII_CHANNEL_TOPIC), UBII_CHANNEL_OPEN);
    ubii_linux_port_destroy(linux_port);
}

TEST_F(InThreadZmtp, MessageOfAnotherShapeIsDroppedAndTheNextOneDelivered)
{
    open_topic();
    Bytes bytes = frame("", true);
    for (const char *part : {"a", "b"}) {
        Bytes more = frame(part, true);
        bytes.insert(bytes.end(), more.begin(), more.end());
    }
    Bytes last = frame("c", false);
    bytes.insert(bytes.end(), last.begin(), last.end());
    Bytes good = routed("good");
    bytes.insert(bytes.end(), good.begin(), good.end());
    peer_.send_bytes(bytes);
    std::vector<std::string> got;
    ASSERT_TRUE(pump_until([&] {
        got = take_all(UBII_CHANNEL_TOPIC);
        return !got.empty();
    }));
    EXPECT_EQ(got, std::vector<std::string>{"good"});
    EXPECT_EQ(state(UBII_CHANNEL_TOPIC), UBII_CHANNEL_OPEN);
    EXPECT_NE(std::string(ubii_linux_port_last_error(linux_port_)).find("dropped"),
              std::string::npos);
}

TEST_F(InThreadZmtp, FrameOverTheLimitLosesTheConnectionWithAReason)
{
    open_topic();
    Bytes bytes = frame("", true);
    Bytes header = {0x02, 0, 0, 0, 0, 0, 0, 0x10, 0}; // LONG, 4096 bytes: over max_message_size
    bytes.insert(bytes.end(), header.begin(), header.end());
    peer_.send_bytes(bytes); // the header alone is enough to refuse it
    ASSERT_TRUE(pump_until([&] { return state(UBII_CHANNEL_TOPIC) == UBII_CHANNEL_LOST; }));
    EXPECT_NE(std::string(ubii_linux_port_last_error(linux_port_)).find("size limit"),
              std::string::npos);
    EXPECT_TRUE(take_all(UBII_CHANNEL_TOPIC).empty());
}

TEST_F(InThreadZmtp, PeerThatIsNotZmtpIsRefusedWithAReason)
{
    ASSERT_EQ(port_.vtable->open(port_.context, UBII_CHANNEL_TOPIC, peer_.url().c_str(), "id"),
              UBII_OK);
    ASSERT_TRUE(pump_until([&] { return peer_.connected(); }));
    std::string http =
        "HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n" + std::string(40, ' ');
    peer_.send_bytes(Bytes(http.begin(), http.end()));
    ASSERT_TRUE(pump_until([&] { return state(UBII_CHANNEL_TOPIC) == UBII_CHANNEL_LOST; }));
    EXPECT_NE(std::string(ubii_linux_port_last_error(linux_port_)).find("ZMTP 3"),
              std::string::npos);
}

TEST_F(InThreadZmtp, ConnectionRefusedAndClosedByThePeerAreLost)
{
    ASSERT_EQ(port_.vtable->open(port_.context, UBII_CHANNEL_TOPIC, "tcp://127.0.0.1:1", "id"),
              UBII_OK);
    EXPECT_TRUE(pump_until([&] { return state(UBII_CHANNEL_TOPIC) == UBII_CHANNEL_LOST; }));

    open_topic();
    peer_.drop_client(); // the master goes away
    EXPECT_TRUE(pump_until([&] { return state(UBII_CHANNEL_TOPIC) == UBII_CHANNEL_LOST; }));
}

// The entries of a /proc folder: the process's threads, or its open fds.
int entries_in(const char *folder)
{
    int count = 0;
    if (DIR *entries = opendir(folder)) {
        while (const dirent *entry = readdir(entries)) {
            count += entry->d_name[0] != '.';
        }
        closedir(entries);
    }
    return count;
}

int thread_count()
{
    return entries_in("/proc/self/task");
}

// With default options a node adds no thread to the process: tcp:// is spoken in the thread that
// polls (a game engine's, a firmware loop's), not through libzmq's I/O threads.
TEST(LinuxPortDefaults, TcpRunsInTheCallersThread)
{
    Peer peer;
    const int threads_before = thread_count();
    ubii_linux_port_options options{};
    options.libwebsockets_log_level = 1;
    ubii_linux_port *linux_port = nullptr;
    ASSERT_EQ(ubii_linux_port_create(&linux_port, &options), UBII_OK);
    ubii_port port = ubii_linux_port_get(linux_port);
    open_topic(port, peer);
    EXPECT_EQ(thread_count(), threads_before);
    ubii_linux_port_destroy(linux_port);
}

int open_fd_count()
{
    return entries_in("/proc/self/fd");
}

bool libwebsockets_mapped()
{
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) {
        if (line.find("libwebsockets") != std::string::npos) {
            return true;
        }
    }
    return false;
}

// A node that speaks only tcp:// never loads libwebsockets (nor the OpenSSL it brings), let alone
// starts it (its context opens pipes of its own): the port holds its wake-up eventfd and one
// socket. Nothing before this test in this program loads it.
TEST(LinuxPortDefaults, TcpOnlyStartsNoLibwebsockets)
{
    Peer peer;
    const int fds_before = open_fd_count();
    ubii_linux_port *linux_port = nullptr;
    ASSERT_EQ(ubii_linux_port_create(&linux_port, nullptr), UBII_OK);
    EXPECT_EQ(open_fd_count(), fds_before + 1) << "the wake-up eventfd only";
    ubii_port port = ubii_linux_port_get(linux_port);
    ASSERT_EQ(port.vtable->open(port.context, UBII_CHANNEL_TOPIC, peer.url().c_str(), "client-7"),
              UBII_OK);
    for (int i = 0; i < 20; ++i) {
        port.vtable->wait(port.context, 5);
    }
    EXPECT_EQ(open_fd_count(), fds_before + 2) << "and the connection's socket";
    EXPECT_FALSE(libwebsockets_mapped());

    // The first ws:// or http:// channel starts it.
    ASSERT_EQ(port.vtable->open(port.context, UBII_CHANNEL_SERVICE, "http://127.0.0.1:1/services",
                                nullptr),
              UBII_OK);
    EXPECT_GT(open_fd_count(), fds_before + 2);
    EXPECT_TRUE(libwebsockets_mapped());
    ubii_linux_port_destroy(linux_port);
    EXPECT_EQ(open_fd_count(), fds_before);
}

// Beside a libwebsockets channel, lws drives the wait: the in-thread connection's traffic must
// still end it. The bound is loose on purpose: a wait of 20 s that ends within 2 s was ended by
// the master's bytes, not by its timeout.
TEST(LinuxPortDefaults, TcpBesideAWebSocketEndsTheWaitThatLibwebsocketsDrives)
{
    Peer peer;
    uint16_t silent_port = 0; // accepts a WebSocket connection and never answers: lws keeps it
    const int silent = ubii_test::listen_on_loopback(silent_port);
    ASSERT_GE(silent, 0);
    ubii_linux_port_options options{};
    options.libwebsockets_log_level = 1;
    ubii_linux_port *linux_port = nullptr;
    ASSERT_EQ(ubii_linux_port_create(&linux_port, &options), UBII_OK);
    ubii_port port = ubii_linux_port_get(linux_port);
    const std::string ws = "ws://127.0.0.1:" + std::to_string(silent_port);
    ASSERT_EQ(port.vtable->open(port.context, UBII_CHANNEL_TOPIC, ws.c_str(), "client-7"), UBII_OK);
    ASSERT_EQ(port.vtable->open(port.context, UBII_CHANNEL_SERVICE, peer.url().c_str(), ""),
              UBII_OK);
    uint8_t *buffer = nullptr;
    ASSERT_EQ(port.vtable->send_begin(port.context, UBII_CHANNEL_SERVICE, 7, &buffer), UBII_OK);
    std::memcpy(buffer, "request", 7);
    ASSERT_EQ(port.vtable->send_commit(port.context, UBII_CHANNEL_SERVICE, 0), UBII_OK);
    auto pump = [&](const std::function<bool()> &done) { return pump_until(port, peer, done); };
    ASSERT_TRUE(pump([&] { return peer.connected() && peer.received.size() >= 64; }));
    peer.send_bytes(peer_handshake("REP"));
    ASSERT_TRUE(pump([&] {
        return std::string(peer.received.begin(), peer.received.end()).find("request") !=
               std::string::npos;
    }));

    peer.send_bytes(routed("reply"));
    const auto start = std::chrono::steady_clock::now();
    port.vtable->wait(port.context, 20000);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
    const uint8_t *data = nullptr;
    size_t size = 0;
    unsigned flags = 0;
    ASSERT_EQ(port.vtable->receive(port.context, UBII_CHANNEL_SERVICE, &data, &size, &flags),
              UBII_OK);
    EXPECT_EQ(std::string(reinterpret_cast<const char *>(data), size), "reply");
    ubii_linux_port_destroy(linux_port);
    close(silent);
}

TEST(InThreadZmtpOptions, UnknownEnginesAreRefused)
{
    ubii_linux_port *port = nullptr;
    ubii_linux_port_options options{};
    const int unknown_engine = 7; // as a C caller may pass; C++ cannot name it
    static_assert(sizeof options.zmq_engine == sizeof unknown_engine, "an int-sized enum");
    std::memcpy(&options.zmq_engine, &unknown_engine, sizeof unknown_engine);
    EXPECT_EQ(ubii_linux_port_create(&port, &options), UBII_ERR_INVALID_ARGUMENT);
}

TEST(InThreadZmtpOptions, TcpUrlsNeedHostAndPortOnly)
{
    ubii_linux_port *linux_port = nullptr;
    ubii_linux_port_options options{};
    options.libwebsockets_log_level = 1;
    options.zmq_engine = UBII_LINUX_ZMQ_IN_THREAD;
    ASSERT_EQ(ubii_linux_port_create(&linux_port, &options), UBII_OK);
    ubii_port port = ubii_linux_port_get(linux_port);
    for (const char *url : {"tcp://127.0.0.1", "tcp://127.0.0.1:8103/path", "tcp://:8103"}) {
        EXPECT_EQ(port.vtable->open(port.context, UBII_CHANNEL_TOPIC, url, "id"),
                  UBII_ERR_INVALID_ARGUMENT)
            << url;
    }
    EXPECT_EQ(port.vtable->open(port.context, UBII_CHANNEL_TOPIC, "tcp://127.0.0.1:8103", ""),
              UBII_ERR_INVALID_ARGUMENT)
        << "a DEALER needs the client id";
    ubii_linux_port_destroy(linux_port);
}

} // namespace
