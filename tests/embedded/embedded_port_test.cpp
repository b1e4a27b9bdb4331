// The embedded port without a master: its HTTP reply parser on hand-written byte streams, split at
// every point (as TCP may deliver them), the HTTP request head it writes, the limits that open()
// and send_begin() check, and the service channel's one buffer against a scripted ZMTP REP peer.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "loopback.h"

extern "C" {
#include "embedded_internal.h"
}

namespace
{

uint64_t zero_ms(void *)
{
    return 0;
}

int64_t zero_epoch(void *)
{
    return 0;
}

void zero_bytes(void *, uint8_t *bytes, size_t count)
{
    std::memset(bytes, 0, count);
}

struct Outcome {
    parse_result result = PARSE_NEED_MORE;
    std::string body;
    std::string error;
};

// A port whose topic channel is set up as an HTTP channel, fed by hand.
class HttpReply : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        ubii_embedded_port_init(&port_, {zero_ms, zero_epoch, zero_bytes, nullptr});
        ch_ = &port_.channels[UBII_CHANNEL_SERVICE];
        ch_->protocol = PROTOCOL_HTTP;
        ch_->phase = PHASE_OPEN;
    }

    // Delivers `stream` in the pieces that `cuts` (ascending offsets) make, parsing after each as
    // the port does, until a message, an error or a dropped reply.
    Outcome feed(const std::string &stream, const std::vector<size_t> &cuts)
    {
        Outcome outcome;
        size_t from = 0;
        std::vector<size_t> ends = cuts;
        ends.push_back(stream.size());
        for (size_t end : ends) {
            while (from < end) {
                size_t room = UBII_EMBEDDED_BUFFER - ch_->rx_used;
                size_t piece = std::min(end - from, room);
                std::memcpy(ch_->rx + ch_->rx_used, stream.data() + from, piece);
                ch_->rx_used += piece;
                from += piece;
                const uint8_t *data = nullptr;
                size_t size = 0, consumed = 0;
                unsigned flags = 0;
                outcome.result =
                    ubii__http_driver.parse(&port_, ch_, &data, &size, &flags, &consumed);
                if (outcome.result == PARSE_MESSAGE) {
                    EXPECT_EQ(data, ch_->rx);
                    EXPECT_EQ(consumed, size);
                    outcome.body.assign(reinterpret_cast<const char *>(data), size);
                }
                if (outcome.result != PARSE_NEED_MORE) {
                    outcome.error = port_.last_error;
                    return outcome;
                }
                if (piece == 0) {
                    outcome.error = "the parser made no room in a full buffer";
                    return outcome;
                }
            }
        }
        return outcome;
    }

    Outcome feed_whole(const std::string &stream)
    {
        return feed(stream, {});
    }

    void reset()
    {
        SetUp();
    }

    ubii_embedded_port port_;
    ubii__embedded_channel *ch_ = nullptr;
};

const std::string chunked_head = "HTTP/1.1 200 OK\r\nX-Powered-By: Express\r\n"
                                 "Content-Type: application/octet-stream\r\n"
                                 "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n";

std::string hex(size_t value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%zx", value);
    return text;
}

TEST_F(HttpReply, ContentLength)
{
    Outcome outcome = feed_whole("HTTP/1.1 200 OK\r\nContent-Type: application/octet-stream\r\n"
                                 "Content-Length: 5\r\nConnection: close\r\n\r\nhello");
    EXPECT_EQ(outcome.result, PARSE_MESSAGE);
    EXPECT_EQ(outcome.body, "hello");
}

TEST_F(HttpReply, EmptyBody)
{
    EXPECT_EQ(feed_whole("HTTP/1.1 200 OK\r\nContent-Length: 0\r\n\r\n").result, PARSE_MESSAGE);
    reset();
    EXPECT_EQ(feed_whole(chunked_head + "0\r\n\r\n").result, PARSE_MESSAGE);
}

TEST_F(HttpReply, ChunkedWithExtensionsAndTrailersAtEverySplit)
{
    const std::string stream = chunked_head + "4;name=value;other=\"quoted;text\"\r\nabcd\r\n"
                                              "00A\r\n0123456789\r\n"
                                              "1 ; spaced\r\n\n\r\n"
                                              "0;last\r\nX-Checksum: 1234\r\nX-Other: yes\r\n\r\n";
    const std::string body = "abcd0123456789\n";
    for (size_t i = 0; i <= stream.size(); ++i) {
        for (size_t j = i; j <= stream.size(); ++j) {
            reset();
            Outcome outcome = feed(stream, {i, j});
            ASSERT_EQ(outcome.result, PARSE_MESSAGE)
                << "cut at " << i << ", " << j << ": " << outcome.error;
            ASSERT_EQ(outcome.body, body) << "cut at " << i << ", " << j;
        }
    }
}

TEST_F(HttpReply, ContentLengthAtEverySplit)
{
    const std::string stream = "HTTP/1.1 200 OK\r\nContent-Length: 11\r\nETag: W/\"b-x\"\r\n\r\n"
                               "hello world";
    for (size_t i = 0; i <= stream.size(); ++i) {
        for (size_t j = i; j <= stream.size(); ++j) {
            reset();
            Outcome outcome = feed(stream, {i, j});
            ASSERT_EQ(outcome.result, PARSE_MESSAGE) << "cut at " << i << ", " << j;
            ASSERT_EQ(outcome.body, "hello world");
        }
    }
}

TEST_F(HttpReply, BareLineFeedsAndUpperCaseHex)
{
    Outcome outcome = feed_whole("HTTP/1.1 200 OK\nTransfer-Encoding: CHUNKED\n\n"
                                 "B\nhello world\n0\n\n");
    EXPECT_EQ(outcome.result, PARSE_MESSAGE) << outcome.error;
    EXPECT_EQ(outcome.body, "hello world");
}

TEST_F(HttpReply, ChunkedOverridesContentLength)
{
    Outcome outcome = feed_whole("HTTP/1.1 200 OK\r\nContent-Length: 100\r\n"
                                 "Transfer-Encoding: chunked\r\n\r\n3\r\nabc\r\n0\r\n\r\n");
    EXPECT_EQ(outcome.result, PARSE_MESSAGE) << outcome.error;
    EXPECT_EQ(outcome.body, "abc");
}

TEST_F(HttpReply, InterimReplyIsSkipped)
{
    Outcome outcome = feed_whole("HTTP/1.1 100 Continue\r\n\r\n"
                                 "HTTP/1.1 200 OK\r\nContent-Length: 2\r\n\r\nok");
    EXPECT_EQ(outcome.result, PARSE_MESSAGE) << outcome.error;
    EXPECT_EQ(outcome.body, "ok");
}

TEST_F(HttpReply, LargestBodyInManyChunksByteByByte)
{
    std::string body(UBII_EMBEDDED_MAX_MESSAGE, '\0');
    for (size_t i = 0; i < body.size(); ++i) {
        body[i] = static_cast<char>('a' + i % 26);
    }
    std::string stream = chunked_head;
    for (size_t at = 0; at < body.size(); at += 100) {
        size_t size = std::min<size_t>(100, body.size() - at);
        stream += hex(size) + ";chunk-extension=" + std::string(40, 'e') + "\r\n" +
                  body.substr(at, size) + "\r\n";
    }
    stream += "0\r\nX-Trailer: " + std::string(300, 't') + "\r\n\r\n";
    ASSERT_GT(stream.size(), static_cast<size_t>(UBII_EMBEDDED_BUFFER)); // framing > headroom
    for (size_t piece : {size_t{1}, size_t{7}, size_t{1000}, stream.size()}) {
        reset();
        std::vector<size_t> cuts;
        for (size_t at = piece; at < stream.size(); at += piece) {
            cuts.push_back(at);
        }
        Outcome outcome = feed(stream, cuts);
        ASSERT_EQ(outcome.result, PARSE_MESSAGE) << "pieces of " << piece << ": " << outcome.error;
        EXPECT_EQ(outcome.body, body);
    }
}

TEST_F(HttpReply, HeadLongerThanTheBufferIsReadLineByLine)
{
    std::string stream = "HTTP/1.1 200 OK\r\n";
    while (stream.size() < 3 * UBII_EMBEDDED_BUFFER) {
        stream += "X-Padding: " + std::string(60, 'p') + "\r\n";
    }
    stream += "Content-Length: 3\r\n\r\nend";
    Outcome outcome = feed_whole(stream);
    EXPECT_EQ(outcome.result, PARSE_MESSAGE) << outcome.error;
    EXPECT_EQ(outcome.body, "end");
}

TEST_F(HttpReply, HeadLineLongerThanTheBufferIsRefused)
{
    Outcome outcome = feed_whole(
        "HTTP/1.1 200 OK\r\nX-Long: " + std::string(UBII_EMBEDDED_BUFFER, 'x') + "\r\n\r\n");
    EXPECT_EQ(outcome.result, PARSE_ERROR);
    EXPECT_NE(outcome.error.find("longer than the buffer"), std::string::npos) << outcome.error;
}

TEST_F(HttpReply, BadChunkSizesAreRefused)
{
    for (const char *bad : {"\r\n", ";ext\r\n", "x\r\n", "4x\r\nabcd\r\n", "4\rX", "-4\r\n",
                            "4\r\nabcdef\r\n", "4\r\nabcdX\n", "0\r\n\rX"}) {
        reset();
        Outcome outcome = feed_whole(chunked_head + bad + "0\r\n\r\n");
        EXPECT_EQ(outcome.result, PARSE_ERROR) << "chunk " << bad;
        EXPECT_NE(outcome.error.find("HTTP"), std::string::npos) << outcome.error;
    }
}

TEST_F(HttpReply, ChunksOverTheLimitAreDropped)
{
    const size_t max = UBII_EMBEDDED_MAX_MESSAGE;
    for (const std::string &chunks :
         {hex(max + 1) + "\r\n", std::string("FFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFF\r\n"),
          hex(max / 2 + 1) + "\r\n" + std::string(max / 2 + 1, 'a') + "\r\n" + hex(max / 2) +
              "\r\n"}) {
        reset();
        Outcome outcome = feed_whole(chunked_head + chunks);
        EXPECT_EQ(outcome.result, PARSE_TOO_LARGE);
        EXPECT_NE(outcome.error.find("over UBII_EMBEDDED_MAX_MESSAGE"), std::string::npos);
    }
    reset();
    EXPECT_EQ(feed_whole(chunked_head + hex(max) + "\r\n").result, PARSE_NEED_MORE); // fits
}

TEST_F(HttpReply, BadHeadsAreRefused)
{
    struct Case {
        std::string head, error;
    };
    for (const Case &bad : std::vector<Case>{
             {"HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\n\r\n", "status 404"},
             {"HTTP/1.1 2000 OK\r\n\r\n", "not an HTTP reply"},
             {"SSH-2.0-OpenSSH\r\n\r\n", "not an HTTP reply"},
             {"HTTP/1.1 200 OK\r\nConnection: close\r\n\r\n", "without Content-Length"},
             {"HTTP/1.1 200 OK\r\nContent-Length: 12a\r\n\r\n", "bad Content-Length"},
             {"HTTP/1.1 200 OK\r\nContent-Length: 3\r\nContent-Length: 4\r\n\r\n",
              "bad Content-Length"},
             {"HTTP/1.1 200 OK\r\nTransfer-Encoding: gzip, chunked\r\n\r\n", "not supported"},
             {"HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\nTransfer-Encoding: chunked\r\n\r\n",
              "not supported"}}) {
        reset();
        Outcome outcome = feed_whole(bad.head);
        EXPECT_EQ(outcome.result, PARSE_ERROR) << bad.head;
        EXPECT_NE(outcome.error.find(bad.error), std::string::npos) << outcome.error;
    }
    reset();
    Outcome outcome = feed_whole("HTTP/1.1 200 OK\r\nContent-Length: 99999999999999999999\r\n\r\n");
    EXPECT_EQ(outcome.result, PARSE_TOO_LARGE);
}

// ---- the request and the port's limits -----------------------------------------------------

class EmbeddedPort : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        ubii_embedded_port_init(&port_, {zero_ms, zero_epoch, zero_bytes, nullptr});
        handle_ = ubii_embedded_port_get(&port_);
    }
    void TearDown() override
    {
        ubii_embedded_port_close(&port_);
    }
    ubii_status open(ubii_channel channel, const std::string &url, const char *id = nullptr)
    {
        return handle_.vtable->open(handle_.context, channel, url.c_str(), id);
    }
    std::string error() const
    {
        return ubii_embedded_port_last_error(&port_);
    }

    ubii_embedded_port port_;
    ubii_port handle_;
};

TEST_F(EmbeddedPort, HttpRequestOfTheLargestMessageFitsWithTheLongestPath)
{
    const std::string path = "/" + std::string(UBII_EMBEDDED_MAX_PATH - 2, 'p');
    ASSERT_EQ(open(UBII_CHANNEL_SERVICE, "http://255.255.255.255:65535" + path), UBII_OK)
        << error();
    uint8_t *buffer = nullptr;
    ASSERT_EQ(handle_.vtable->send_begin(handle_.context, UBII_CHANNEL_SERVICE,
                                         UBII_EMBEDDED_MAX_MESSAGE, &buffer),
              UBII_OK);
    std::memset(buffer, 'b', UBII_EMBEDDED_MAX_MESSAGE);
    ubii__embedded_channel *ch = &port_.channels[UBII_CHANNEL_SERVICE];
    ubii__http_driver.frame(&port_, ch, ch->reserved_at, ch->reserved, 0);
    const std::string head = "POST " + path +
                             " HTTP/1.1\r\nHost: 255.255.255.255:65535\r\n"
                             "Content-Type: application/octet-stream\r\nContent-Length: " +
                             std::to_string(UBII_EMBEDDED_MAX_MESSAGE) +
                             "\r\nConnection: close\r\n\r\n";
    ASSERT_EQ(ch->reserved_at, head.size());
    EXPECT_EQ(std::string(reinterpret_cast<char *>(ch->tx), head.size()), head);
    EXPECT_EQ(
        std::string(reinterpret_cast<char *>(ch->tx) + head.size(), UBII_EMBEDDED_MAX_MESSAGE),
        std::string(UBII_EMBEDDED_MAX_MESSAGE, 'b')); // the body's first byte survives
    ch->header_room = 0;
}

TEST_F(EmbeddedPort, OverLargeMessagesAreRefused)
{
    ASSERT_EQ(open(UBII_CHANNEL_SERVICE, "http://127.0.0.1:9/services/binary"), UBII_OK);
    uint8_t *buffer = nullptr;
    EXPECT_EQ(handle_.vtable->send_begin(handle_.context, UBII_CHANNEL_SERVICE,
                                         UBII_EMBEDDED_MAX_MESSAGE + 1, &buffer),
              UBII_ERR_TOO_LARGE);
}

TEST_F(EmbeddedPort, UrlsThatDoNotFitAreRefused)
{
    const std::string longest = "/" + std::string(UBII_EMBEDDED_MAX_PATH - 2, 'p');
    EXPECT_EQ(open(UBII_CHANNEL_SERVICE, "http://127.0.0.1:9" + longest), UBII_OK);
    EXPECT_EQ(open(UBII_CHANNEL_SERVICE, "http://127.0.0.1:9" + longest + "p"),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_NE(error().find("UBII_EMBEDDED_MAX_PATH"), std::string::npos) << error();
    EXPECT_EQ(open(UBII_CHANNEL_SERVICE, "http://localhost:9/"), UBII_ERR_INVALID_ARGUMENT);
    EXPECT_NE(error().find("IPv4"), std::string::npos) << error();

    const std::string uuid = "0123abcd-0123-4567-89ab-0123456789ab";
    // "?clientID=" and the id go into the path too.
    const std::string ws_path(UBII_EMBEDDED_MAX_PATH - 1 - 10 - uuid.size(), '/');
    EXPECT_EQ(open(UBII_CHANNEL_TOPIC, "ws://127.0.0.1:9" + ws_path, uuid.c_str()), UBII_OK);
    EXPECT_EQ(open(UBII_CHANNEL_TOPIC, "ws://127.0.0.1:9" + ws_path + "/", uuid.c_str()),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_NE(error().find("clientID"), std::string::npos) << error();
}

TEST_F(EmbeddedPort, ClientIdsThatDoNotFitAreRefused)
{
    const std::string longest(sizeof port_.channels[0].identity - 1, 'i');
    EXPECT_EQ(open(UBII_CHANNEL_TOPIC, "tcp://127.0.0.1:9", longest.c_str()), UBII_OK);
    EXPECT_EQ(open(UBII_CHANNEL_TOPIC, "tcp://127.0.0.1:9", (longest + "i").c_str()),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_NE(error().find("client id"), std::string::npos) << error();
    EXPECT_EQ(open(UBII_CHANNEL_TOPIC, "tcp://127.0.0.1:9", ""), UBII_ERR_INVALID_ARGUMENT);
}

// ---- the service channel's one buffer -------------------------------------------------------

// A ZMTP 3.0 REP peer on loopback that answers two requests ("reply to " and the request); after
// the first reply it sends `extra` in the same write, as a peer may send a heartbeat command
// between replies.
class ZmtpRepPeer
{
  public:
    explicit ZmtpRepPeer(std::string extra) : extra_(std::move(extra))
    {
        listener_ = ubii_test::listen_on_loopback(port_);
        if (listener_ < 0) {
            ADD_FAILURE() << "no listening socket";
        }
        thread_ = std::thread([this] { serve(); });
    }
    ~ZmtpRepPeer()
    {
        thread_.join();
        close(listener_);
    }
    uint16_t port() const
    {
        return port_;
    }
    static std::string frame(uint8_t flags, const std::string &body)
    {
        return std::string(1, static_cast<char>(flags)) +
               std::string(1, static_cast<char>(body.size())) + body;
    }
    static std::string message(const std::string &payload)
    {
        return frame(0x01, "") + frame(0x00, payload); // delimiter, payload
    }

  private:
    bool read_exactly(int fd, size_t size, std::string &out)
    {
        out.resize(size);
        for (size_t got = 0; got < size;) {
            ssize_t n = recv(fd, &out[got], size - got, 0);
            if (n <= 0) {
                return false;
            }
            got += static_cast<size_t>(n);
        }
        return true;
    }
    void serve()
    {
        // Bounded waits, so that a failing client cannot hang the test.
        pollfd listening = {listener_, POLLIN, 0};
        if (poll(&listening, 1, 5000) != 1) {
            return;
        }
        int fd = accept(listener_, nullptr, nullptr);
        timeval timeout = {5, 0};
        setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
        std::string greeting(64, '\0'), ignored;
        greeting[0] = '\xFF';
        greeting[9] = '\x7F';
        greeting[10] = 3;
        greeting.replace(12, 4, "NULL");
        std::string ready = "\x05READY\x0BSocket-Type" + std::string("\0\0\0\x03", 4) + "REP";
        std::string out = greeting + frame(0x04, ready);
        send(fd, out.data(), out.size(), 0);
        std::string head;
        // The client's greeting, its READY (short command frame), then two requests.
        if (read_exactly(fd, 64, ignored) && read_exactly(fd, 2, head) &&
            read_exactly(fd, static_cast<uint8_t>(head[1]), ignored)) {
            for (int i = 1; i <= 2; ++i) {
                std::string body;
                if (!read_exactly(fd, 4, head) ||
                    !read_exactly(fd, static_cast<uint8_t>(head[3]), body)) {
                    break;
                }
                out = message("reply to " + body) + (i == 1 ? extra_ : "");
                send(fd, out.data(), out.size(), 0);
            }
        }
        read_exactly(fd, 1, ignored); // until the client closes
        close(fd);
    }

    std::string extra_;
    int listener_ = -1;
    uint16_t port_ = 0;
    std::thread thread_;
};

// Sends `request` on the service channel and returns the reply's text ("" on timeout).
std::string call(ubii_embedded_port &port, const std::string &request)
{
    ubii_port handle = ubii_embedded_port_get(&port);
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    uint8_t *buffer = nullptr;
    while (handle.vtable->send_begin(handle.context, UBII_CHANNEL_SERVICE, request.size(),
                                     &buffer) != UBII_OK) {
        if (std::chrono::steady_clock::now() > deadline) {
            return "";
        }
        handle.vtable->wait(handle.context, 10);
    }
    std::memcpy(buffer, request.data(), request.size());
    EXPECT_EQ(handle.vtable->send_commit(handle.context, UBII_CHANNEL_SERVICE, 0), UBII_OK);
    const uint8_t *data;
    size_t size;
    unsigned flags;
    while (handle.vtable->receive(handle.context, UBII_CHANNEL_SERVICE, &data, &size, &flags) !=
           UBII_OK) {
        if (std::chrono::steady_clock::now() > deadline) {
            return "";
        }
        handle.vtable->wait(handle.context, 10);
    }
    return std::string(reinterpret_cast<const char *>(data), size);
}

class SharedServiceBuffer : public ::testing::TestWithParam<bool>
{
};

TEST_P(SharedServiceBuffer, WhatThePeerSendsBetweenRepliesIsClearedBeforeTheNextRequest)
{
    const bool stray_message = GetParam();
    const std::string heartbeat = ZmtpRepPeer::frame(0x04, "\x04PING" + std::string(2, '\0'));
    ZmtpRepPeer peer(stray_message ? ZmtpRepPeer::message("stray") : heartbeat);
    struct ClosedAtTheEnd {
        ubii_embedded_port port;
        ~ClosedAtTheEnd()
        {
            ubii_embedded_port_close(&port);
        }
    } owner;
    ubii_embedded_port &port = owner.port;
    ubii_embedded_port_init(&port, ubii_embedded_posix_platform());
    ubii_port handle = ubii_embedded_port_get(&port);
    const std::string url = "tcp://127.0.0.1:" + std::to_string(peer.port());
    ASSERT_EQ(handle.vtable->open(handle.context, UBII_CHANNEL_SERVICE, url.c_str(), nullptr),
              UBII_OK);

    EXPECT_EQ(call(port, "request-1"), "reply to request-1");
    // What came after the reply sits behind it in the one buffer the next request needs.
    const ubii__embedded_channel &ch = port.channels[UBII_CHANNEL_SERVICE];
    for (int i = 0; i < 100 && ch.rx_used == ch.lent_size; ++i) {
        handle.vtable->wait(handle.context, 10);
    }
    ASSERT_GT(ch.rx_used, ch.lent_size);
    EXPECT_EQ(call(port, "request-2"), "reply to request-2")
        << ubii_embedded_port_last_error(&port);
    EXPECT_EQ(port.decode_errors, stray_message ? 1u : 0u);
}

INSTANTIATE_TEST_SUITE_P(HeartbeatOrStrayMessage, SharedServiceBuffer, ::testing::Bool());

} // namespace
