/* hello: asks a Ubi-Interact master for its server configuration and prints it.
 *
 *   hello [SERVICE_URL]    default: $UBII_SERVICE_URL, else tcp://127.0.0.1:8101
 *
 * One request over a ZMQ REQ socket, encoded and decoded with libubii's service codec. Gives up
 * after UBII_HELLO_TIMEOUT_MS (default 3000 ms) instead of waiting for an absent master forever. */
#include <stdio.h>
#include <stdlib.h>

#include <zmq.h>

#include "ubii/service_codec.h"
#include "ubii/version.h"

enum { MESSAGE_CAPACITY = 8192 };

static int timeout_ms(void)
{
    const char *text = getenv("UBII_HELLO_TIMEOUT_MS");
    int value = text != NULL ? atoi(text) : 0;
    return value > 0 ? value : 3000;
}

/* Sends `request` and waits for one reply. Returns the reply size, or -1 with a message printed. */
static int request_reply(const char *url, const uint8_t *request, size_t request_length,
                         uint8_t *reply, size_t reply_capacity)
{
    int result = -1;
    int timeout = timeout_ms();
    int linger = 0;
    void *context = zmq_ctx_new();
    void *socket = zmq_socket(context, ZMQ_REQ);
    zmq_setsockopt(socket, ZMQ_LINGER, &linger, sizeof linger);
    zmq_setsockopt(socket, ZMQ_RCVTIMEO, &timeout, sizeof timeout);
    zmq_setsockopt(socket, ZMQ_SNDTIMEO, &timeout, sizeof timeout);
    if (zmq_connect(socket, url) != 0) {
        fprintf(stderr, "hello: cannot connect to %s: %s\n", url, zmq_strerror(zmq_errno()));
    } else if (zmq_send(socket, request, request_length, 0) < 0) {
        fprintf(stderr, "hello: sending to %s failed: %s\n", url, zmq_strerror(zmq_errno()));
    } else {
        result = zmq_recv(socket, reply, reply_capacity, 0);
        if (result < 0) {
            fprintf(stderr, "hello: no reply from %s within %d ms\n", url, timeout);
        } else if ((size_t)result > reply_capacity) {
            fprintf(stderr, "hello: reply of %d bytes is larger than %zu\n", result,
                    reply_capacity);
            result = -1;
        }
    }
    zmq_close(socket);
    zmq_ctx_term(context);
    return result;
}

int main(int argc, char **argv)
{
    const char *url = argc > 1 ? argv[1] : getenv("UBII_SERVICE_URL");
    if (url == NULL) {
        url = "tcp://127.0.0.1:8101";
    }

    static uint8_t request[512];
    static uint8_t reply[MESSAGE_CAPACITY];
    size_t request_length = 0;
    ubii_status status = ubii_encode_topic_request("/services/server_configuration", request,
                                                   sizeof request, &request_length);
    if (status != UBII_OK) {
        fprintf(stderr, "hello: %s\n", ubii_strerror(status));
        return 1;
    }
    int reply_length = request_reply(url, request, request_length, reply, sizeof reply);
    if (reply_length < 0) {
        return 1;
    }

    ubii_servers_Server server;
    ubii_broker_error error;
    status = ubii_decode_server_reply(reply, (size_t)reply_length, &server, &error);
    if (status == UBII_ERR_BROKER) {
        fprintf(stderr, "hello: the master answered with an error: %s: %s\n", error.title,
                error.message);
        return 1;
    }
    if (status != UBII_OK) {
        fprintf(stderr, "hello: %s\n", ubii_strerror(status));
        return 1;
    }

    printf("libubii %s asked %s for its configuration:\n", ubii_version(), url);
    printf("  master id          %s\n", server.id);
    printf("  name               %s\n", server.name);
    printf("  ip ethernet / wlan '%s' / '%s'\n", server.ip_ethernet, server.ip_wlan);
    printf("  service ports      zmq %s, http %s\n", server.port_service_zmq,
           server.port_service_rest);
    printf("  topic data ports   zmq %s, websocket %s\n", server.port_topic_data_zmq,
           server.port_topic_data_ws);
    return 0;
}
