// The node's protocol logic against a scripted in-process master (FakePort) with simulated time:
// sequence, keepalive, subscriptions, duplicates, bad input, timeouts, reconnection, stop.
#include <algorithm>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "fake_port.h"
#include "pb_test_callbacks.h"
#include "ubii/ubii.h"

using namespace ubii_test;

namespace
{

const std::string client_id = "11111111-2222-4333-8444-555555555555";

class NodeWithFakeMaster : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        fake.answer = [this](const ubii_services_ServiceRequest &request)
            -> std::optional<std::vector<uint8_t>> {
            std::string topic = request.topic;
            if (topic == UBII_SERVICE_SERVER_CONFIGURATION) {
                return server_reply();
            }
            if (topic == UBII_SERVICE_CLIENT_REGISTRATION) {
                return registration_fails ? error_reply("ClientRegistrationService", "no")
                                          : client_reply(client_id);
            }
            if (topic == UBII_SERVICE_TOPIC_SUBSCRIPTION ||
                topic == UBII_SERVICE_CLIENT_DEREGISTRATION) {
                return success_reply();
            }
            if (topic == "/services/slow") {
                return std::nullopt;
            }
            return error_reply("Service request error", "unknown topic: " + topic);
        };
        ubii_config_init(&config);
        config.service_url = "tcp://fake:8101";
        config.client_name = "fake-test";
        config.service_timeout_ms = 1000;
        config.ping_timeout_ms = 3000;
        config.reconnect_min_ms = 100;
        config.reconnect_max_ms = 400;
        config.on_state = [](ubii_node *, ubii_state, ubii_state current, ubii_status reason,
                             void *user) {
            auto *self = static_cast<NodeWithFakeMaster *>(user);
            self->states.push_back(current);
            self->reasons.push_back(reason);
        };
        config.on_state_user = this;
        config.on_error = [](ubii_node *, ubii_status status, const char *detail, void *user) {
            static_cast<NodeWithFakeMaster *>(user)->errors.emplace_back(status, detail);
        };
        config.on_error_user = this;
    }

    void init()
    {
        ASSERT_EQ(ubii_node_init(&node, sizeof node, &config, fake.port()), UBII_OK);
    }

    void start_ready()
    {
        init();
        ASSERT_EQ(ubii_node_start(&node), UBII_OK);
        poll(5);
        ASSERT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    }

    void leave_deregistrations_unanswered()
    {
        auto answer = fake.answer;
        fake.answer = [answer](const ubii_services_ServiceRequest &request) {
            return std::string(request.topic) == UBII_SERVICE_CLIENT_DEREGISTRATION
                       ? std::nullopt
                       : answer(request);
        };
    }

    void poll(int times, int timeout_ms = 0)
    {
        for (int i = 0; i < times; ++i) {
            ubii_node_poll(&node, timeout_ms);
        }
    }

    // Advances simulated time by polling with a timeout.
    void advance(int milliseconds)
    {
        uint64_t until = fake.now + static_cast<uint64_t>(milliseconds);
        while (fake.now < until) {
            ubii_node_poll(&node, static_cast<int>(until - fake.now));
        }
    }

    FakePort fake;
    ubii_config config;
    ubii_node node;
    bool registration_fails = false;
    std::vector<ubii_state> states;
    std::vector<ubii_status> reasons;
    std::vector<std::pair<ubii_status, std::string>> errors;
};

struct Counter {
    int count = 0;
    double last = 0;
    static void on_record(ubii_node *, const ubii_record *record, void *user)
    {
        auto *self = static_cast<Counter *>(user);
        self->count++;
        ubii_record_double(record, &self->last);
    }
};

TEST_F(NodeWithFakeMaster, ConnectsInProtocolOrderAndOpensTopicsWithTheClientId)
{
    start_ready();
    ASSERT_GE(fake.requests.size(), 2u);
    EXPECT_STREQ(fake.requests[0].topic, UBII_SERVICE_SERVER_CONFIGURATION);
    EXPECT_STREQ(fake.requests[1].topic, UBII_SERVICE_CLIENT_REGISTRATION);
    ASSERT_EQ(fake.requests[1].which_type, ubii_services_ServiceRequest_client_tag);
    EXPECT_STREQ(fake.requests[1].type.client.name, "fake-test");
    EXPECT_EQ(fake.topic_client_id, client_id);
    EXPECT_STREQ(ubii_node_client_id(&node), client_id.c_str());
    std::vector<ubii_state> expected = {UBII_STATE_CONNECTING, UBII_STATE_REGISTERING,
                                        UBII_STATE_OPENING, UBII_STATE_READY};
    EXPECT_EQ(states, expected);
}

TEST_F(NodeWithFakeMaster, TellsTheTimeItsTimeoutsRunOn)
{
    start_ready();
    EXPECT_EQ(ubii_node_monotonic_ms(&node), fake.now);
    advance(250);
    EXPECT_EQ(ubii_node_monotonic_ms(&node), fake.now);
    EXPECT_EQ(ubii_node_monotonic_ms(nullptr), 0u);
}

TEST_F(NodeWithFakeMaster, StateChangesFromStartAreAnnouncedOnlyInsidePoll)
{
    init();
    ASSERT_EQ(ubii_node_start(&node), UBII_OK);
    EXPECT_TRUE(states.empty());
    ubii_node_poll(&node, 0);
    ASSERT_FALSE(states.empty());
    EXPECT_EQ(states.front(), UBII_STATE_CONNECTING);
}

TEST_F(NodeWithFakeMaster, AnswersEveryPingWithAPongOfTheSameFrameKind)
{
    start_ready();
    fake.push_topic({'P', 'I', 'N', 'G'}, UBII_MESSAGE_TEXT);
    fake.push_topic({'P', 'I', 'N', 'G'}, 0);
    poll(1);
    ASSERT_EQ(fake.topic_sent.size(), 2u);
    EXPECT_EQ(fake.topic_sent[0].bytes, (std::vector<uint8_t>{'P', 'O', 'N', 'G'}));
    EXPECT_EQ(fake.topic_sent[0].flags, UBII_MESSAGE_TEXT);
    EXPECT_EQ(fake.topic_sent[1].flags, 0u);
    ubii_stats stats;
    ubii_node_stats(&node, &stats);
    EXPECT_EQ(stats.pings, 2u);
}

TEST_F(NodeWithFakeMaster, AsksTheMasterOncePerPatternAndAgainAfterReconnecting)
{
    start_ready();
    Counter a, b, c;
    ubii_subscription first = 0;
    ASSERT_EQ(ubii_subscribe(&node, "/t", Counter::on_record, &a, &first), UBII_OK);
    ASSERT_EQ(ubii_subscribe(&node, "/t", Counter::on_record, &b, nullptr), UBII_OK);
    ASSERT_EQ(ubii_subscribe_regex(&node, "^/r/.*", Counter::on_record, &c, nullptr), UBII_OK);
    poll(3);
    EXPECT_EQ(fake.subscribe_topics, std::vector<std::string>{"/t"});
    EXPECT_EQ(fake.subscribe_regexes, std::vector<std::string>{"^/r/.*"});

    ASSERT_EQ(ubii_unsubscribe(&node, first), UBII_OK);
    poll(3);
    EXPECT_TRUE(fake.unsubscribe_topics.empty()); // "/t" still has a subscriber

    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(1);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    advance(150);
    poll(5);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    EXPECT_EQ(fake.subscribe_topics, (std::vector<std::string>{"/t", "/t"}));
    EXPECT_EQ(fake.subscribe_regexes, (std::vector<std::string>{"^/r/.*", "^/r/.*"}));
}

TEST_F(NodeWithFakeMaster, CopiesForOverlappingSubscriptionsAreDeliveredOnce)
{
    start_ready();
    Counter exact, regex;
    ASSERT_EQ(ubii_subscribe(&node, "/a", Counter::on_record, &exact, nullptr), UBII_OK);
    ASSERT_EQ(ubii_subscribe_regex(&node, "^/a$", Counter::on_record, &regex, nullptr), UBII_OK);
    poll(3);
    // The current master sends a record once per matching subscription, back to back.
    auto record = double_record("/a", 1.0);
    fake.push_topic(record);
    fake.push_topic(record);
    poll(1);
    EXPECT_EQ(exact.count, 1);
    EXPECT_EQ(regex.count, 1);
    // A second, identical publication is a new record.
    fake.push_topic(record);
    fake.push_topic(record);
    poll(1);
    EXPECT_EQ(exact.count, 2);
    EXPECT_EQ(regex.count, 2);
    ubii_stats stats;
    ubii_node_stats(&node, &stats);
    EXPECT_EQ(stats.duplicates_dropped, 2u);
}

TEST_F(NodeWithFakeMaster, IdenticalRecordsOnASingleSubscriptionAreAllDelivered)
{
    start_ready();
    Counter counter;
    ASSERT_EQ(ubii_subscribe(&node, "/a", Counter::on_record, &counter, nullptr), UBII_OK);
    poll(3);
    for (int i = 0; i < 3; ++i) {
        fake.push_topic(double_record("/a", 7.0));
    }
    poll(1);
    EXPECT_EQ(counter.count, 3);
    EXPECT_EQ(counter.last, 7.0);
}

TEST_F(NodeWithFakeMaster, MalformedTopicDataIsCountedAndReportedNeverFatal)
{
    start_ready();
    Counter counter;
    ASSERT_EQ(ubii_subscribe_regex(&node, ".*", Counter::on_record, &counter, nullptr), UBII_OK);
    poll(3);
    fake.push_topic({0x12, 0x05, 0x0a}); // a record whose length runs past the end
    poll(1);
    ubii_stats stats;
    ubii_node_stats(&node, &stats);
    EXPECT_EQ(stats.decode_errors, 1u);
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors.back().first, UBII_ERR_DECODE);

    std::mt19937 random(42);
    for (int i = 0; i < 2000; ++i) {
        std::vector<uint8_t> garbage(random() % 64);
        for (auto &byte : garbage) {
            byte = static_cast<uint8_t>(random());
        }
        fake.push_topic(garbage);
    }
    poll(1);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    fake.push_topic(double_record("/after", 3.0));
    poll(1);
    EXPECT_EQ(counter.last, 3.0);
}

TEST_F(NodeWithFakeMaster, TopicsOverTheSizeLimitAreRefused)
{
    start_ready();
    Counter counter;
    ASSERT_EQ(ubii_subscribe_regex(&node, ".*", Counter::on_record, &counter, nullptr), UBII_OK);
    poll(3);
    // Written by hand: our own encoder refuses such a topic.
    std::vector<uint8_t> bytes = {0x12};
    std::string topic(300, 't');
    std::vector<uint8_t> record = {0x0a, 0xac, 0x02};
    record.insert(record.end(), topic.begin(), topic.end());
    bytes.push_back(static_cast<uint8_t>(record.size() | 0x80));
    bytes.push_back(static_cast<uint8_t>(record.size() >> 7));
    bytes.insert(bytes.end(), record.begin(), record.end());
    fake.push_topic(bytes);
    poll(1);
    EXPECT_EQ(counter.count, 0);
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors.back().first, UBII_ERR_TOO_LARGE);
}

TEST_F(NodeWithFakeMaster, TopicDataErrorsFromTheMasterAreReported)
{
    start_ready();
    fake.push_topic(topic_data_error("TopicData reception failed (Client ID x)"));
    poll(1);
    ubii_stats stats;
    ubii_node_stats(&node, &stats);
    EXPECT_EQ(stats.master_errors, 1u);
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors.back().first, UBII_ERR_BROKER);
    EXPECT_EQ(errors.back().second, "TopicData reception failed (Client ID x)");
}

struct Reply {
    bool done = false;
    ubii_status status = UBII_OK;
    std::string message;
    static void on_reply(ubii_node *, const ubii_reply *reply, void *user)
    {
        auto *self = static_cast<Reply *>(user);
        self->done = true;
        self->status = reply->status;
        self->message = reply->error_message;
    }
};

TEST_F(NodeWithFakeMaster, AnUnansweredCallTimesOutAndTheChannelStartsAfresh)
{
    start_ready();
    int service_opens = fake.opens[UBII_CHANNEL_SERVICE];
    Reply slow, next;
    ASSERT_EQ(ubii_call_topic(&node, "/services/slow", 500, Reply::on_reply, &slow), UBII_OK);
    ASSERT_EQ(ubii_call_topic(&node, "/services/other", 0, Reply::on_reply, &next), UBII_OK);
    advance(400);
    EXPECT_FALSE(slow.done);
    advance(200);
    ASSERT_TRUE(slow.done);
    EXPECT_EQ(slow.status, UBII_ERR_TIMEOUT);
    EXPECT_EQ(fake.opens[UBII_CHANNEL_SERVICE], service_opens + 1);
    poll(2);
    ASSERT_TRUE(next.done);
    EXPECT_EQ(next.status, UBII_ERR_BROKER);
    EXPECT_EQ(next.message, "unknown topic: /services/other");
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
}

TEST_F(NodeWithFakeMaster, ARefusedRegistrationIsRetriedWithGrowingBackoff)
{
    registration_fails = true;
    init();
    ASSERT_EQ(ubii_node_start(&node), UBII_OK);
    poll(3);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    EXPECT_EQ(reasons.back(), UBII_ERR_BROKER);
    advance(99);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING); // first wait: 100 ms (t = 1100)
    advance(1);
    poll(3);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING); // failed again at t = 1100
    advance(199);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING); // second wait: 200 ms
    registration_fails = false;
    advance(1);
    poll(5);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
}

TEST_F(NodeWithFakeMaster, SilenceAfterTheFirstPingMeansTheMasterIsLost)
{
    start_ready();
    advance(5000); // no PING yet: the watchdog is not armed (the npm 0.4.0 master never pings)
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    fake.push_topic({'P', 'I', 'N', 'G'});
    poll(1);
    advance(2900);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    advance(200);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    EXPECT_EQ(reasons.back(), UBII_ERR_TIMEOUT);
}

TEST_F(NodeWithFakeMaster, ATopicConnectionThatNeverOpensTimesOut)
{
    fake.topic_opens = false;
    init();
    ASSERT_EQ(ubii_node_start(&node), UBII_OK);
    poll(3);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_OPENING);
    advance(999);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_OPENING);
    advance(2);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    EXPECT_EQ(reasons.back(), UBII_ERR_TIMEOUT);
}

// Each retry registers anew: a node that lost only its topic data connection tells the master to
// forget its old registration first, over the service channel that still works.
std::vector<std::string> request_topics(const FakePort &fake, size_t from = 0)
{
    std::vector<std::string> topics;
    for (size_t i = from; i < fake.requests.size(); ++i) {
        topics.emplace_back(fake.requests[i].topic);
    }
    return topics;
}

TEST_F(NodeWithFakeMaster, ALostTopicConnectionIsDeregisteredBeforeTheRetry)
{
    start_ready();
    const size_t before = fake.requests.size();
    const int service_opens = fake.opens[UBII_CHANNEL_SERVICE];
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(2);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    EXPECT_EQ(reasons.back(), UBII_ERR_TRANSPORT);
    ASSERT_EQ(request_topics(fake, before),
              std::vector<std::string>{UBII_SERVICE_CLIENT_DEREGISTRATION});
    EXPECT_STREQ(fake.requests.back().type.client.id, client_id.c_str());
    EXPECT_EQ(fake.state(UBII_CHANNEL_SERVICE), UBII_CHANNEL_CLOSED); // closed once answered
    advance(100);
    poll(5);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    EXPECT_EQ(fake.opens[UBII_CHANNEL_SERVICE], service_opens + 1);
    std::vector<std::string> expected = {UBII_SERVICE_CLIENT_DEREGISTRATION,
                                         UBII_SERVICE_SERVER_CONFIGURATION,
                                         UBII_SERVICE_CLIENT_REGISTRATION};
    std::vector<std::string> sent = request_topics(fake, before);
    sent.resize(std::min(sent.size(), expected.size()));
    EXPECT_EQ(sent, expected);
    EXPECT_TRUE(errors.empty()) << errors.front().second;
}

// A REQ channel with a request in flight is reset (closed and reopened) when the call is cancelled,
// but not when it closes right after: no connection attempt is made only to be dropped.
TEST_F(NodeWithFakeMaster, ALostServiceChannelIsNotReopenedOnlyToBeClosed)
{
    start_ready();
    Reply pending;
    ASSERT_EQ(ubii_call_topic(&node, "/services/slow", 0, Reply::on_reply, &pending), UBII_OK);
    poll(1);
    ASSERT_FALSE(pending.done);
    const int service_opens = fake.opens[UBII_CHANNEL_SERVICE];
    fake.set_state(UBII_CHANNEL_SERVICE, UBII_CHANNEL_LOST);
    poll(1);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    EXPECT_TRUE(pending.done);
    EXPECT_EQ(pending.status, UBII_ERR_CANCELLED);
    EXPECT_EQ(fake.state(UBII_CHANNEL_SERVICE), UBII_CHANNEL_CLOSED);
    EXPECT_EQ(fake.opens[UBII_CHANNEL_SERVICE], service_opens);
}

TEST_F(NodeWithFakeMaster, AMasterThatIsGoneIsNotAskedToDeregister)
{
    start_ready();
    const size_t before = fake.requests.size();
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    fake.set_state(UBII_CHANNEL_SERVICE, UBII_CHANNEL_LOST);
    poll(2);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    EXPECT_EQ(fake.requests.size(), before);
    advance(100);
    poll(5);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
}

TEST_F(NodeWithFakeMaster, AnUnansweredDeregistrationHoldsTheRetryForTheServiceTimeoutOnly)
{
    start_ready();
    leave_deregistrations_unanswered();
    const size_t before = fake.requests.size();
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(1);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    EXPECT_EQ(ubii_node_next_timeout_ms(&node), 1000); // the call's deadline, not the backoff's
    advance(999);
    EXPECT_EQ(fake.requests.size(), before + 1); // backoff over, deregistration still pending
    advance(1);
    poll(5);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors.back().first, UBII_ERR_TIMEOUT);
}

TEST_F(NodeWithFakeMaster, ANodeThatGivesUpDeregistersEveryAttempt)
{
    fake.topic_opens = false;
    config.max_reconnect_attempts = 1;
    init();
    ASSERT_EQ(ubii_node_start(&node), UBII_OK);
    poll(3);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_OPENING);
    advance(1001); // the topic connection did not open in time
    poll(2);
    advance(100); // backoff
    poll(3);
    advance(1001); // nor the second time
    poll(2);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_FAILED);
    const std::vector<std::string> sent = request_topics(fake);
    EXPECT_EQ(std::count(sent.begin(), sent.end(), UBII_SERVICE_CLIENT_REGISTRATION), 2);
    EXPECT_EQ(std::count(sent.begin(), sent.end(), UBII_SERVICE_CLIENT_DEREGISTRATION), 2);
    EXPECT_EQ(sent.back(), UBII_SERVICE_CLIENT_DEREGISTRATION);
    EXPECT_EQ(fake.state(UBII_CHANNEL_SERVICE), UBII_CHANNEL_CLOSED);
}

TEST_F(NodeWithFakeMaster, StopDuringADeregistrationAfterALossWaitsForIt)
{
    start_ready();
    leave_deregistrations_unanswered();
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(1);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    const size_t before = fake.requests.size();
    ASSERT_EQ(ubii_node_stop(&node), UBII_OK);
    poll(1);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_STOPPING);
    EXPECT_EQ(fake.requests.size(), before); // the same deregistration, not a second one
    advance(1000);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_STOPPED);
    EXPECT_EQ(fake.state(UBII_CHANNEL_SERVICE), UBII_CHANNEL_CLOSED);
}

// Neither master drops a client's subscriptions when it deregisters (docs/PROTOCOL.md §2.8): the
// node releases them itself first.
TEST_F(NodeWithFakeMaster, StopReleasesEverySubscriptionBeforeDeregistering)
{
    start_ready();
    Counter counter;
    ASSERT_EQ(ubii_subscribe(&node, "/a", Counter::on_record, &counter, nullptr), UBII_OK);
    ASSERT_EQ(ubii_subscribe(&node, "/a", Counter::on_record, &counter, nullptr), UBII_OK);
    ASSERT_EQ(ubii_subscribe_regex(&node, "^/b", Counter::on_record, &counter, nullptr), UBII_OK);
    poll(3);
    const size_t before = fake.requests.size();
    ASSERT_EQ(ubii_node_stop(&node), UBII_OK);
    poll(3);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_STOPPED);
    EXPECT_EQ(request_topics(fake, before),
              (std::vector<std::string>{UBII_SERVICE_TOPIC_SUBSCRIPTION,
                                        UBII_SERVICE_CLIENT_DEREGISTRATION}));
    EXPECT_STREQ(fake.requests[before].type.topic_subscription.client_id, client_id.c_str());
    EXPECT_EQ(fake.unsubscribe_topics, std::vector<std::string>{"/a"});
    EXPECT_EQ(fake.unsubscribe_regexes, std::vector<std::string>{"^/b"});
    EXPECT_TRUE(errors.empty()) << errors.front().second;
}

TEST_F(NodeWithFakeMaster, ALostTopicConnectionReleasesSubscriptionsBeforeDeregistering)
{
    start_ready();
    Counter counter;
    ASSERT_EQ(ubii_subscribe(&node, "/a", Counter::on_record, &counter, nullptr), UBII_OK);
    poll(3);
    const size_t before = fake.requests.size();
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(3);
    EXPECT_EQ(request_topics(fake, before),
              (std::vector<std::string>{UBII_SERVICE_TOPIC_SUBSCRIPTION,
                                        UBII_SERVICE_CLIENT_DEREGISTRATION}));
    EXPECT_EQ(fake.unsubscribe_topics, std::vector<std::string>{"/a"});
    advance(100);
    poll(5);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    EXPECT_EQ(fake.subscribe_topics, (std::vector<std::string>{"/a", "/a"})); // asked again
}

// The master went away while the node was leaving: the unanswered release and deregistration
// are dropped with the channel, and the next connection starts with its own requests.
TEST_F(NodeWithFakeMaster, AServiceChannelLostWhileLeavingLeavesNothingQueued)
{
    start_ready();
    Counter counter;
    ASSERT_EQ(ubii_subscribe(&node, "/a", Counter::on_record, &counter, nullptr), UBII_OK);
    poll(3);
    auto answer = fake.answer;
    fake.answer = [](const ubii_services_ServiceRequest &) { return std::nullopt; };
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(1);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    fake.set_state(UBII_CHANNEL_SERVICE, UBII_CHANNEL_LOST);
    poll(1);
    fake.answer = answer;
    advance(100);
    poll(5);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
}

TEST_F(NodeWithFakeMaster, StopCancelsPendingCallsDeregistersAndCloses)
{
    start_ready();
    Reply pending;
    ASSERT_EQ(ubii_call_topic(&node, "/services/slow", 0, Reply::on_reply, &pending), UBII_OK);
    poll(1);
    ASSERT_EQ(ubii_node_stop(&node), UBII_OK);
    EXPECT_FALSE(pending.done); // nothing runs outside poll
    poll(3);
    EXPECT_TRUE(pending.done);
    EXPECT_EQ(pending.status, UBII_ERR_CANCELLED);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_STOPPED);
    const auto &last = fake.requests.back();
    EXPECT_STREQ(last.topic, UBII_SERVICE_CLIENT_DEREGISTRATION);
    EXPECT_STREQ(last.type.client.id, client_id.c_str());
    EXPECT_EQ(fake.state(UBII_CHANNEL_TOPIC), UBII_CHANNEL_CLOSED);
    EXPECT_EQ(fake.state(UBII_CHANNEL_SERVICE), UBII_CHANNEL_CLOSED);
}

TEST_F(NodeWithFakeMaster, CallbacksCannotPollReentrantly)
{
    start_ready();
    ubii_status nested = UBII_OK; // per run: a static would let --gtest_repeat pass on stale state
    auto record_fn = [](ubii_node *n, const ubii_record *, void *user) {
        *static_cast<ubii_status *>(user) = ubii_node_poll(n, 0);
    };
    ASSERT_EQ(ubii_subscribe(&node, "/a", record_fn, &nested, nullptr), UBII_OK);
    poll(3);
    fake.push_topic(double_record("/a", 1.0));
    poll(1);
    EXPECT_EQ(nested, UBII_ERR_STATE);
}

TEST_F(NodeWithFakeMaster, PublishedRecordsCarryTopicTimestampAndValue)
{
    start_ready();
    ASSERT_EQ(ubii_publish_double(&node, "/out", 1.0), UBII_OK);
    ASSERT_EQ(fake.topic_sent.size(), 1u);
    // TopicData{record{topic "/out", timestamp{millis 1700000000000}, double 1.0}}, as Python's
    // protobuf encodes it.
    EXPECT_EQ(to_hex(fake.topic_sent[0].bytes.data(), fake.topic_sent[0].bytes.size()),
              "12180a042f6f757412071880d095ffbc3119000000000000f03f");
}

} // namespace

namespace
{

TEST_F(NodeWithFakeMaster, TypedHelpersEncodeLikeTheGenericMessagePublish)
{
    start_ready();
    ubii_dataStructure_Pose3D pose = ubii_dataStructure_Pose3D_init_zero;
    pose.has_position = true;
    pose.position.x = 1;
    pose.which_orientation = ubii_dataStructure_Pose3D_euler_tag;
    pose.orientation.euler.z = 2;
    ASSERT_EQ(ubii_publish_pose3d(&node, "/p", &pose), UBII_OK);
    ASSERT_EQ(ubii_publish_message(&node, "/p", UBII_RECORD_POSE3D,
                                   ubii_dataStructure_Pose3D_fields, &pose),
              UBII_OK);
    ubii_dataStructure_Color color = {0.1, 0.2, 0.3, 1.0};
    ASSERT_EQ(ubii_publish_color(&node, "/c", &color), UBII_OK);
    ASSERT_EQ(fake.topic_sent.size(), 3u);
    EXPECT_EQ(fake.topic_sent[0].bytes, fake.topic_sent[1].bytes);
    EXPECT_EQ(ubii_node_size(), sizeof(ubii_node));
}

} // namespace

namespace
{

TEST_F(NodeWithFakeMaster, WhileStoppingPingsAreAnsweredAndRecordsNotPassedOn)
{
    start_ready();
    Counter counter;
    ASSERT_EQ(ubii_subscribe(&node, "/a", Counter::on_record, &counter, nullptr), UBII_OK);
    poll(3);
    // The deregistration goes unanswered for a while: the node stays STOPPING.
    fake.answer = [](const ubii_services_ServiceRequest &) { return std::nullopt; };
    ASSERT_EQ(ubii_node_stop(&node), UBII_OK);
    poll(1);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_STOPPING);
    size_t sent_before = fake.topic_sent.size();
    fake.push_topic(double_record("/a", 1.0));
    fake.push_topic({'P', 'I', 'N', 'G'}, UBII_MESSAGE_TEXT);
    poll(1);
    EXPECT_EQ(counter.count, 0);
    ASSERT_EQ(fake.topic_sent.size(), sent_before + 1);
    EXPECT_EQ(fake.topic_sent.back().bytes, (std::vector<uint8_t>{'P', 'O', 'N', 'G'}));
    advance(1100); // the deregistration times out; the node stops anyway
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_STOPPED);
}

} // namespace

namespace
{

// ubii_publish_encoded: a member encoded by another protobuf runtime goes out byte for byte as the
// nanopb path would write it.
TEST_F(NodeWithFakeMaster, EncodedMembersPublishLikeTheirNanopbTwins)
{
    start_ready();
    ubii_dataStructure_Vector3 vector = {1.5, -2, 3};
    ASSERT_EQ(ubii_publish_vector3(&node, "/v", &vector), UBII_OK);
    // Vector3{x 1.5, y -2, z 3}: three fixed64 fields.
    const std::vector<uint8_t> body = {0x09, 0, 0, 0, 0, 0, 0, 0xf8, 0x3f,
                                       0x11, 0, 0, 0, 0, 0, 0, 0,    0xc0,
                                       0x19, 0, 0, 0, 0, 0, 0, 0x08, 0x40};
    ASSERT_EQ(ubii_publish_encoded(&node, "/v", UBII_RECORD_VECTOR3, body.data(), body.size()),
              UBII_OK);
    ASSERT_EQ(fake.topic_sent.size(), 2u);
    EXPECT_EQ(fake.topic_sent[0].bytes, fake.topic_sent[1].bytes);
}

TEST_F(NodeWithFakeMaster, EncodedPublishRefusesScalarAndUnknownMembers)
{
    start_ready();
    const uint8_t byte = 1;
    EXPECT_EQ(ubii_publish_encoded(&node, "/x", UBII_RECORD_DOUBLE, &byte, 1),
              UBII_ERR_INVALID_ARGUMENT);
    // 33 is TopicDataRecord.client_id, not a value member.
    EXPECT_EQ(ubii_publish_encoded(&node, "/x", static_cast<ubii_record_type>(33), &byte, 1),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_publish_encoded(&node, "/x", UBII_RECORD_VECTOR3, nullptr, 1),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_TRUE(fake.topic_sent.empty());
}

// ubii_call_encoded: the bytes reach the master as given and the reply comes back as for
// ubii_call; bytes the master could not route are refused before they are queued.
TEST_F(NodeWithFakeMaster, EncodedCallsAreSentAsGivenAndAnswered)
{
    start_ready();
    const size_t before = fake.requests.size();
    // ServiceRequest{topic "/services/other"}
    const std::string topic = "/services/other";
    std::vector<uint8_t> request = {0x0a, static_cast<uint8_t>(topic.size())};
    request.insert(request.end(), topic.begin(), topic.end());
    Reply reply;
    ASSERT_EQ(ubii_call_encoded(&node, request.data(), request.size(), 0, Reply::on_reply, &reply),
              UBII_OK);
    poll(2);
    ASSERT_EQ(fake.requests.size(), before + 1);
    EXPECT_EQ(std::string(fake.requests.back().topic), topic);
    ASSERT_TRUE(reply.done);
    EXPECT_EQ(reply.status, UBII_ERR_BROKER);
    EXPECT_EQ(reply.message, "unknown topic: /services/other");

    const uint8_t truncated[] = {0x0a, 0x05, '/', 'a'};
    EXPECT_EQ(ubii_call_encoded(&node, truncated, sizeof truncated, 0, nullptr, nullptr),
              UBII_ERR_INVALID_ARGUMENT);
    const uint8_t no_topic[] = {0x12, 0x00}; // an empty client, no topic
    EXPECT_EQ(ubii_call_encoded(&node, no_topic, sizeof no_topic, 0, nullptr, nullptr),
              UBII_ERR_INVALID_ARGUMENT);
    std::vector<uint8_t> oversized(UBII_SERVICE_QUEUE_BYTES + 16, 0);
    oversized[0] = 0x0a;
    oversized[1] = 0x01;
    oversized[2] = '/';
    oversized[3] = 0x22; // a topic_subscription member filling the rest
    size_t rest = oversized.size() - 6;
    oversized[4] = static_cast<uint8_t>(0x80 | (rest & 0x7f));
    oversized[5] = static_cast<uint8_t>(rest >> 7);
    EXPECT_EQ(ubii_call_encoded(&node, oversized.data(), oversized.size(), 0, nullptr, nullptr),
              UBII_ERR_TOO_LARGE);
}

#ifdef UBII_PROCESSING_H
// The names of the processing modules a registration request offers (Client.processing_modules),
// and whether it says the client is a dedicated processing node.
struct OfferedModules {
    std::vector<std::string> names;
    bool dedicated = false;
};

OfferedModules offered_in(const std::vector<uint8_t> &request_bytes)
{
    StringValues specs;
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    request.cb_type.arg = &specs;
    request.cb_type.funcs.decode = [](pb_istream_t *, const pb_field_t *field, void **arg) {
        if (field->tag == ubii_services_ServiceRequest_client_tag) {
            auto *client = static_cast<ubii_clients_Client *>(field->pData);
            decode_into(client->processing_modules, *static_cast<StringValues *>(*arg));
        }
        return true;
    };
    pb_istream_t stream = pb_istream_from_buffer(request_bytes.data(), request_bytes.size());
    OfferedModules offered;
    if (!pb_decode(&stream, ubii_services_ServiceRequest_fields, &request))
        return offered;
    offered.dedicated = request.type.client.is_dedicated_processing_node;
    for (const std::string &bytes : specs.values) {
        ubii_processing_ProcessingModule spec = ubii_processing_ProcessingModule_init_zero;
        pb_istream_t spec_stream =
            pb_istream_from_buffer(reinterpret_cast<const uint8_t *>(bytes.data()), bytes.size());
        offered.names.push_back(
            pb_decode(&spec_stream, ubii_processing_ProcessingModule_fields, &spec) ? spec.name
                                                                                    : "<invalid>");
    }
    return offered;
}

std::vector<uint8_t> encoded_spec(const char *name)
{
    ubii_processing_ProcessingModule spec = ubii_processing_ProcessingModule_init_zero;
    strncpy(spec.name, name, sizeof spec.name - 1);
    std::vector<uint8_t> bytes(256);
    pb_ostream_t stream = pb_ostream_from_buffer(bytes.data(), bytes.size());
    EXPECT_TRUE(pb_encode(&stream, ubii_processing_ProcessingModule_fields, &spec));
    bytes.resize(stream.bytes_written);
    return bytes;
}

std::vector<std::vector<uint8_t>> registrations(const FakePort &fake)
{
    std::vector<std::vector<uint8_t>> found;
    for (size_t i = 0; i < fake.requests.size(); ++i) {
        if (std::string(fake.requests[i].topic) == UBII_SERVICE_CLIENT_REGISTRATION)
            found.push_back(fake.request_bytes[i]);
    }
    return found;
}

TEST_F(NodeWithFakeMaster, OfferedProcessingModulesGoWithEveryRegistration)
{
    const std::vector<uint8_t> sum = encoded_spec("sum"), ocr = encoded_spec("ocr");
    const ubii_encoded_message specs[] = {{sum.data(), sum.size()}, {ocr.data(), ocr.size()}};
    config.is_dedicated_processing_node = true;
    init();
    ASSERT_EQ(ubii_node_offer_processing_modules(&node, specs, 2), UBII_OK);
    ASSERT_EQ(ubii_node_start(&node), UBII_OK);
    poll(5);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_READY);

    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(2);
    advance(150);
    poll(5);
    ASSERT_EQ(ubii_node_state(&node), UBII_STATE_READY);
    const auto sent = registrations(fake);
    ASSERT_EQ(sent.size(), 2u);
    for (const auto &registration : sent) {
        const OfferedModules offered = offered_in(registration);
        EXPECT_EQ(offered.names, (std::vector<std::string>{"sum", "ocr"}));
        EXPECT_TRUE(offered.dedicated);
    }

    // Offering none takes effect at the next registration.
    ASSERT_EQ(ubii_node_offer_processing_modules(&node, nullptr, 0), UBII_OK);
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    poll(2);
    advance(150);
    poll(5);
    ASSERT_EQ(registrations(fake).size(), 3u);
    EXPECT_TRUE(offered_in(registrations(fake).back()).names.empty());
}

TEST_F(NodeWithFakeMaster, OfferedModulesThatOverfillTheQueueFailTheAttemptVisibly)
{
    std::vector<uint8_t> huge(UBII_SERVICE_QUEUE_BYTES, 'x');
    huge[0] = 0x12; // name (2), length-delimited, filling the rest
    huge[1] = static_cast<uint8_t>(0x80 | ((huge.size() - 3) & 0x7f));
    huge[2] = static_cast<uint8_t>((huge.size() - 3) >> 7);
    const ubii_encoded_message spec = {huge.data(), huge.size()};
    init();
    ASSERT_EQ(ubii_node_offer_processing_modules(&node, &spec, 1), UBII_OK);
    ASSERT_EQ(ubii_node_start(&node), UBII_OK);
    poll(5);
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_RECONNECTING);
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors.front().first, UBII_ERR_TOO_LARGE);
    EXPECT_NE(errors.front().second.find("registration"), std::string::npos);
    EXPECT_TRUE(registrations(fake).empty());
}

TEST_F(NodeWithFakeMaster, OfferingModulesChecksItsArguments)
{
    init();
    const ubii_encoded_message no_bytes = {nullptr, 3};
    EXPECT_EQ(ubii_node_offer_processing_modules(nullptr, nullptr, 0), UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_node_offer_processing_modules(&node, nullptr, 1), UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_node_offer_processing_modules(&node, &no_bytes, 1), UBII_ERR_INVALID_ARGUMENT);
}
#endif

TEST(RecordTypeTable, NamesAndFormatsComeFromTheSchema)
{
    EXPECT_STREQ(ubii_record_type_name(UBII_RECORD_VECTOR3), "vector3");
    EXPECT_STREQ(ubii_record_type_format(UBII_RECORD_VECTOR3), "ubii.dataStructure.Vector3");
    EXPECT_STREQ(ubii_record_type_format(UBII_RECORD_DOUBLE), "double");
    EXPECT_STREQ(ubii_record_type_name(UBII_RECORD_OBJECT2D_LIST), "object2D_list");
    EXPECT_EQ(ubii_record_type_for_format("ubii.dataStructure.Object2DList"),
              UBII_RECORD_OBJECT2D_LIST);
    // Two members hold a Quaternion (upstream's quaternion_list quirk): the lower number wins.
    EXPECT_EQ(ubii_record_type_for_format("ubii.dataStructure.Quaternion"), UBII_RECORD_QUATERNION);
    EXPECT_EQ(ubii_record_type_for_format("ubii.dataStructure.NoSuchThing"), UBII_RECORD_NONE);
    EXPECT_EQ(ubii_record_type_for_format(nullptr), UBII_RECORD_NONE);
    EXPECT_EQ(ubii_record_type_name(UBII_RECORD_NONE), nullptr);
}

} // namespace
