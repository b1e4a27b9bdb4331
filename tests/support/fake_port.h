#ifndef UBII_TEST_FAKE_PORT_H
#define UBII_TEST_FAKE_PORT_H

// An in-process port for unit tests: a scripted master. Service requests are answered by a
// function the test sets; topic messages are queued by the test; everything the node sends is
// recorded. Time is simulated: wait() advances the clock instead of sleeping.

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ubii/port.h"
#include "ubii/services/serviceRequest.pb.h"

namespace ubii_test
{

struct SentMessage {
    std::vector<uint8_t> bytes;
    unsigned flags;
};

class FakePort
{
  public:
    FakePort();
    ubii_port port();

    // Answers each service request; std::nullopt means no reply (the node's timeout fires).
    std::function<std::optional<std::vector<uint8_t>>(const ubii_services_ServiceRequest &)> answer;
    // Whether the topic channel reaches OPEN when opened (else it stays CONNECTING).
    bool topic_opens = true;

    void push_topic(const std::vector<uint8_t> &bytes, unsigned flags = 0);
    void set_state(ubii_channel channel, ubii_channel_state state);
    ubii_channel_state state(ubii_channel channel) const
    {
        return channels_[channel].state;
    }

    std::vector<ubii_services_ServiceRequest> requests; // decoded, in order
    std::vector<std::vector<uint8_t>> request_bytes;    // the same as they were sent
    std::vector<std::string> subscribe_topics, subscribe_regexes, unsubscribe_topics,
        unsubscribe_regexes; // from every TopicSubscription request
    std::vector<SentMessage> topic_sent;
    std::string topic_client_id;
    int opens[UBII_CHANNEL_COUNT] = {0, 0};
    uint64_t now = 1000;
    int64_t epoch = 1700000000000;

  private:
    struct Channel {
        ubii_channel_state state = UBII_CHANNEL_CLOSED;
        std::deque<SentMessage> inbox;
        SentMessage current;
        std::vector<uint8_t> outgoing;
    };
    void on_service_request(const std::vector<uint8_t> &bytes);

    static ubii_status open(void *, ubii_channel, const char *, const char *);
    static void close(void *, ubii_channel);
    static ubii_channel_state get_state(void *, ubii_channel);
    static ubii_status send_begin(void *, ubii_channel, size_t, uint8_t **);
    static ubii_status send_commit(void *, ubii_channel, unsigned);
    static ubii_status receive(void *, ubii_channel, const uint8_t **, size_t *, unsigned *);
    static ubii_status wait(void *, int);
    static int pollfds(void *, ubii_pollfd *, int);
    static uint64_t monotonic(void *);
    static int64_t epoch_ms(void *);

    Channel channels_[UBII_CHANNEL_COUNT];
};

// Encoders for the replies and topic data a test scripts.
std::vector<uint8_t> server_reply(const std::string &topic_port = "8103");
std::vector<uint8_t> client_reply(const std::string &id);
std::vector<uint8_t> success_reply();
std::vector<uint8_t> error_reply(const std::string &title, const std::string &message);
std::vector<uint8_t> double_record(const std::string &topic, double value);
std::vector<uint8_t> topic_data_error(const std::string &title);

} // namespace ubii_test

#endif
