// Proves the harness: the real master started by the fixture answers a nanopb-encoded
// /services/server_configuration request over ZMQ REQ with a Server message naming its ports.
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <zmq.h>

#include "ubii/service_codec.h"

namespace
{

int port_base()
{
    const char *text = std::getenv("UBII_TEST_PORT_BASE");
    return text != nullptr ? std::atoi(text) : 8101;
}

// One REQ/REP exchange with a receive timeout; an empty result means no reply in time.
std::vector<uint8_t> request_reply(const std::string &url, const uint8_t *request, size_t length)
{
    void *context = zmq_ctx_new();
    void *socket = zmq_socket(context, ZMQ_REQ);
    int timeout_ms = 5000, linger = 0;
    zmq_setsockopt(socket, ZMQ_RCVTIMEO, &timeout_ms, sizeof timeout_ms);
    zmq_setsockopt(socket, ZMQ_LINGER, &linger, sizeof linger);
    std::vector<uint8_t> reply(16384);
    int received = -1;
    if (zmq_connect(socket, url.c_str()) == 0 && zmq_send(socket, request, length, 0) >= 0) {
        received = zmq_recv(socket, reply.data(), reply.size(), 0);
    }
    zmq_close(socket);
    zmq_ctx_term(context);
    reply.resize(received > 0 && static_cast<size_t>(received) <= reply.size() ? received : 0);
    return reply;
}

TEST(MasterSmoke, ServerConfigurationOverZmqReturnsTheMastersPorts)
{
    uint8_t request[256];
    size_t length = 0;
    ASSERT_EQ(ubii_encode_topic_request("/services/server_configuration", request, sizeof request,
                                        &length),
              UBII_OK);

    const int base = port_base();
    auto reply = request_reply("tcp://127.0.0.1:" + std::to_string(base), request, length);
    ASSERT_FALSE(reply.empty()) << "no reply from the master within 5 s";

    ubii_servers_Server server;
    ubii_broker_error error{};
    ASSERT_EQ(ubii_decode_server_reply(reply.data(), reply.size(), &server, &error), UBII_OK)
        << error.title << ": " << error.message;
    EXPECT_EQ(std::string(server.port_service_zmq), std::to_string(base));
    EXPECT_EQ(std::string(server.port_service_rest), std::to_string(base + 1));
    EXPECT_EQ(std::string(server.port_topic_data_zmq), std::to_string(base + 2));
    EXPECT_EQ(std::string(server.port_topic_data_ws), std::to_string(base + 3));
}

TEST(MasterSmoke, UnknownServiceTopicIsABrokerError)
{
    uint8_t request[256];
    size_t length = 0;
    ASSERT_EQ(
        ubii_encode_topic_request("/services/does_not_exist", request, sizeof request, &length),
        UBII_OK);
    auto reply = request_reply("tcp://127.0.0.1:" + std::to_string(port_base()), request, length);
    ASSERT_FALSE(reply.empty()) << "no reply from the master within 5 s";

    ubii_servers_Server server;
    ubii_broker_error error{};
    ASSERT_EQ(ubii_decode_server_reply(reply.data(), reply.size(), &server, &error),
              UBII_ERR_BROKER);
    // The wording differs between master versions (0.4.0: "Ubii service request processing
    // failed"; current: "unknown topic: <topic>"); both are Error replies with a title.
    EXPECT_GT(std::strlen(error.title), 0u) << error.message;
}

} // namespace
