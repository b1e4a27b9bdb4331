// How a node subscribes, counts subscriptions, calls services and reports trouble, against the
// real master.
#include <cstring>
#include <map>

#include <gtest/gtest.h>

#include "test_node.h"
#include "test_port.h"
#include "ubii/dataStructure/lists.pb.h"
#include "ubii/devices/device.pb.h"

using ubii_test::TestNode;
using ubii_test::unique_topic;

namespace
{

// Counts records per subscription, by the `user` pointer each subscription was given.
struct Counter {
    int count = 0;
    static void on_record(ubii_node *, const ubii_record *, void *user)
    {
        static_cast<Counter *>(user)->count++;
    }
};

void poll_for(TestNode &node, int milliseconds)
{
    auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(milliseconds);
    node.poll_until([&] { return std::chrono::steady_clock::now() >= until; });
}

TEST(Subscriptions, RegexReceivesMatchingTopicsOnly)
{
    TestNode node("regex-test");
    ASSERT_TRUE(node.wait_ready());
    const std::string base = unique_topic("/regex");
    node.collect("^" + base + "/[ab]$", true);
    // /b goes last: the master forwards one publisher's records in order, so by the time a /b
    // arrives, every /c and /ab published before it would have arrived too.
    ASSERT_TRUE(node.poll_until([&] {
        ubii_publish_int32(node.get(), (base + "/a").c_str(), 1);
        ubii_publish_int32(node.get(), (base + "/c").c_str(), 3);
        ubii_publish_int32(node.get(), (base + "/ab").c_str(), 4);
        ubii_publish_int32(node.get(), (base + "/b").c_str(), 2);
        std::map<std::string, int> seen;
        for (const auto &r : node.received()) {
            seen[r.topic]++;
        }
        return seen.count(base + "/a") && seen.count(base + "/b");
    }));
    for (const auto &r : node.received()) {
        EXPECT_TRUE(r.topic == base + "/a" || r.topic == base + "/b") << r.topic;
    }
}

TEST(Subscriptions, OverlappingExactAndRegexDeliverEachRecordOncePerSubscription)
{
    TestNode node("overlap-test");
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = unique_topic("/overlap");
    Counter exact, regex;
    ASSERT_EQ(ubii_subscribe(node.get(), topic.c_str(), Counter::on_record, &exact, nullptr),
              UBII_OK);
    ASSERT_EQ(ubii_subscribe_regex(node.get(), (topic + "$").c_str(), Counter::on_record, &regex,
                                   nullptr),
              UBII_OK);
    // Warm up until the master serves both subscriptions, then count one publication.
    ASSERT_TRUE(node.poll_until([&] {
        ubii_publish_double(node.get(), topic.c_str(), 0.0);
        return exact.count > 0 && regex.count > 0;
    }));
    poll_for(node, 300);
    exact.count = regex.count = 0;
    ubii_stats before;
    ubii_node_stats(node.get(), &before);
    ASSERT_EQ(ubii_publish_double(node.get(), topic.c_str(), 1.0), UBII_OK);
    poll_for(node, 500);
    EXPECT_EQ(exact.count, 1);
    EXPECT_EQ(regex.count, 1);
    ubii_stats after;
    ubii_node_stats(node.get(), &after);
    // The current master sends one copy per matching subscription, the npm 0.4.0 master one in
    // all; either way the node passes on one record (fake_port_test covers the two-copy case).
    EXPECT_EQ(after.records_received - before.records_received, 1u);
    EXPECT_LE(after.duplicates_dropped - before.duplicates_dropped, 1u);
}

TEST(Subscriptions, UnsubscribeIsCountedLocally)
{
    TestNode node("refcount-test");
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = unique_topic("/refcount");
    Counter first, second;
    ubii_subscription a = 0, b = 0;
    ASSERT_EQ(ubii_subscribe(node.get(), topic.c_str(), Counter::on_record, &first, &a), UBII_OK);
    ASSERT_EQ(ubii_subscribe(node.get(), topic.c_str(), Counter::on_record, &second, &b), UBII_OK);
    ASSERT_TRUE(node.poll_until([&] {
        ubii_publish_bool(node.get(), topic.c_str(), true);
        return first.count > 0 && second.count > 0;
    }));

    // One of two gone: the master keeps sending, the other subscriber keeps receiving.
    ASSERT_EQ(ubii_unsubscribe(node.get(), a), UBII_OK);
    EXPECT_EQ(ubii_unsubscribe(node.get(), a), UBII_ERR_NOT_FOUND);
    poll_for(node, 300);
    first.count = second.count = 0;
    ASSERT_EQ(ubii_publish_bool(node.get(), topic.c_str(), true), UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return second.count > 0; }, std::chrono::seconds(3)));
    EXPECT_EQ(first.count, 0);

    // The last one gone: the master is told, and records stop arriving at all.
    ASSERT_EQ(ubii_unsubscribe(node.get(), b), UBII_OK);
    poll_for(node, 500);
    ubii_stats before;
    ubii_node_stats(node.get(), &before);
    for (int i = 0; i < 5; ++i) {
        ASSERT_EQ(ubii_publish_bool(node.get(), topic.c_str(), false), UBII_OK);
    }
    poll_for(node, 500);
    ubii_stats after;
    ubii_node_stats(node.get(), &after);
    EXPECT_EQ(after.records_received, before.records_received);
    EXPECT_EQ(second.count, 1);
}

TEST(Subscriptions, TwoNodesInOneProcessWorkIndependently)
{
    TestNode publisher("two-nodes-publisher");
    TestNode subscriber("two-nodes-subscriber");
    ASSERT_TRUE(publisher.wait_ready());
    ASSERT_TRUE(subscriber.wait_ready());
    EXPECT_STRNE(ubii_node_client_id(publisher.get()), ubii_node_client_id(subscriber.get()));
    const std::string topic = unique_topic("/two-nodes");
    subscriber.collect(topic);
    ASSERT_TRUE(subscriber.poll_until([&] {
        ubii_node_poll(publisher.get(), 0);
        ubii_publish_string(publisher.get(), topic.c_str(), "hello", 5);
        return !subscriber.received().empty();
    }));
    EXPECT_EQ(std::string(subscriber.received().front().value.begin(),
                          subscriber.received().front().value.end()),
              "hello");
    EXPECT_TRUE(publisher.received().empty());
}

// ---- services ---------------------------------------------------------------------------------

struct ReplyCatcher {
    bool done = false;
    ubii_status status = UBII_OK;
    uint32_t member = 0;
    std::string title, message;
    std::vector<std::string> strings;
    static void on_reply(ubii_node *, const ubii_reply *reply, void *user)
    {
        auto *self = static_cast<ReplyCatcher *>(user);
        self->done = true;
        self->status = reply->status;
        self->member = reply->member;
        self->title = reply->error_title;
        self->message = reply->error_message;
        ubii_field_iter it;
        const uint8_t *text;
        size_t length;
        ubii_field_iter_init(&it, reply->bytes, reply->size, 1);
        while (reply->member == ubii_services_ServiceReply_string_list_tag &&
               ubii_field_iter_next(&it, &text, &length)) {
            self->strings.emplace_back(reinterpret_cast<const char *>(text), length);
        }
    }
};

// Neither master drops a client's subscriptions when it deregisters (docs/PROTOCOL.md §2.8); the
// node releases them before it deregisters. A raw topic connection under the stopped node's old id
// (its routing id or ?clientID=) then receives nothing the master would still forward to it.
TEST(Subscriptions, AStoppedNodeLeavesNoSubscriptionAtTheMaster)
{
    TestNode publisher("release-publisher");
    ASSERT_TRUE(publisher.wait_ready());
    const std::string topic = unique_topic("/release");
    std::string old_id;
    {
        TestNode node("release-test");
        ASSERT_TRUE(node.wait_ready());
        node.collect(topic);
        node.collect("^" + topic + "$", true);
        ASSERT_TRUE(node.poll_until([&] {
            ubii_publish_double(publisher.get(), topic.c_str(), 1.0);
            ubii_node_poll(publisher.get(), 0);
            return node.received().size() >= 2; // one copy per subscription
        }));
        old_id = ubii_node_client_id(node.get());
        ASSERT_EQ(ubii_node_stop_wait(node.get(), 3000), UBII_OK);
        EXPECT_TRUE(node.errors().empty()) << node.errors().front().second;
    }
    ubii_test::TestPort raw_port;
    ubii_port raw = raw_port.get();
    ASSERT_EQ(raw.vtable->open(raw.context, UBII_CHANNEL_TOPIC, ubii_test::topic_zmq_url().c_str(),
                               old_id.c_str()),
              UBII_OK);
    auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (raw.vtable->state(raw.context, UBII_CHANNEL_TOPIC) != UBII_CHANNEL_OPEN &&
           std::chrono::steady_clock::now() < until) {
        raw.vtable->wait(raw.context, 10);
    }
    ASSERT_EQ(raw.vtable->state(raw.context, UBII_CHANNEL_TOPIC), UBII_CHANNEL_OPEN);
    int forwarded = 0;
    until = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
    while (std::chrono::steady_clock::now() < until) {
        ubii_publish_double(publisher.get(), topic.c_str(), 2.0);
        ubii_node_poll(publisher.get(), 0);
        raw.vtable->wait(raw.context, 10);
        const uint8_t *data;
        size_t size;
        unsigned flags;
        while (raw.vtable->receive(raw.context, UBII_CHANNEL_TOPIC, &data, &size, &flags) ==
               UBII_OK) {
            forwarded += size != 4 || std::memcmp(data, "PING", 4) != 0;
        }
    }
    raw.vtable->close(raw.context, UBII_CHANNEL_TOPIC);
    EXPECT_EQ(forwarded, 0) << "the master still forwards to " << old_id;
}

TEST(Services, TopicListNamesAPublishedTopic)
{
    TestNode node("topic-list-test");
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = unique_topic("/listed");
    ASSERT_EQ(ubii_publish_double(node.get(), topic.c_str(), 1.0), UBII_OK);
    poll_for(node, 200);
    ReplyCatcher catcher;
    ASSERT_EQ(
        ubii_call_topic(node.get(), UBII_SERVICE_TOPIC_LIST, 0, ReplyCatcher::on_reply, &catcher),
        UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return catcher.done; }));
    ASSERT_EQ(catcher.status, UBII_OK) << catcher.title << ": " << catcher.message;
    ASSERT_EQ(catcher.member, static_cast<uint32_t>(ubii_services_ServiceReply_string_list_tag));
    EXPECT_NE(std::find(catcher.strings.begin(), catcher.strings.end(), topic),
              catcher.strings.end());
}

TEST(Services, UnknownServiceTopicIsABrokerError)
{
    TestNode node("unknown-service-test");
    ASSERT_TRUE(node.wait_ready());
    ReplyCatcher catcher;
    ASSERT_EQ(ubii_call_topic(node.get(), "/services/does_not_exist", 0, ReplyCatcher::on_reply,
                              &catcher),
              UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return catcher.done; }));
    EXPECT_EQ(catcher.status, UBII_ERR_BROKER);
    EXPECT_FALSE(catcher.title.empty());
    // The node carries on.
    ReplyCatcher next;
    ASSERT_EQ(
        ubii_call_topic(node.get(), UBII_SERVICE_TOPIC_LIST, 0, ReplyCatcher::on_reply, &next),
        UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return next.done; }));
    EXPECT_EQ(next.status, UBII_OK);
}

// A TopicSubscription request, with no topics, on behalf of `client_id`.
ubii_services_ServiceRequest subscription_request_for(const std::string &client_id)
{
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    std::strcpy(request.topic, UBII_SERVICE_TOPIC_SUBSCRIPTION);
    request.which_type = ubii_services_ServiceRequest_topic_subscription_tag;
    std::strcpy(request.type.topic_subscription.client_id, client_id.c_str());
    return request;
}

TEST(Services, SubscribingForAnUnknownClientIdIsABrokerError)
{
    TestNode node("unknown-client-test");
    ASSERT_TRUE(node.wait_ready());
    ubii_services_ServiceRequest request =
        subscription_request_for("00000000-0000-4000-8000-000000000000");
    ReplyCatcher catcher;
    ASSERT_EQ(ubii_call(node.get(), &request, 0, ReplyCatcher::on_reply, &catcher), UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return catcher.done; }));
    EXPECT_EQ(catcher.status, UBII_ERR_BROKER);
    EXPECT_NE(catcher.message.find("00000000-0000-4000-8000-000000000000"), std::string::npos)
        << catcher.title << ": " << catcher.message;
}

// Every retry registers anew. A node whose topic data connection fails while the master still
// answers its services deregisters before it retries or gives up, so the master keeps no client
// per attempt: subscribing for any of those ids is then an unknown-client error.
TEST(Services, ANodeWhoseTopicConnectionFailsLeavesNoRegistrationBehind)
{
    TestNode witness("registration-witness");
    ASSERT_TRUE(witness.wait_ready());
    TestNode node("failed-topic-test", "tcp://127.0.0.1:9"); // nothing listens there
    node.config().service_timeout_ms = 500;                  // how long OPENING may take
    ASSERT_TRUE(node.start_and_wait_failed(1));
    ASSERT_EQ(node.registered_ids().size(), 2u);
    poll_for(node, 1000); // the last deregistration, bounded by the service timeout
    for (const std::string &id : node.registered_ids()) {
        ubii_services_ServiceRequest request = subscription_request_for(id);
        ReplyCatcher catcher;
        ASSERT_EQ(ubii_call(witness.get(), &request, 0, ReplyCatcher::on_reply, &catcher), UBII_OK);
        ASSERT_TRUE(witness.poll_until([&] { return catcher.done; }));
        EXPECT_EQ(catcher.status, UBII_ERR_BROKER) << id << " is still registered";
    }
    for (const auto &error : node.errors()) {
        EXPECT_NE(error.second, "deregistration failed") << ubii_strerror(error.first);
    }
}

struct DeviceCatcher {
    bool done = false;
    ubii_status status = UBII_OK;
    ubii_devices_Device device = ubii_devices_Device_init_zero;
    static void on_reply(ubii_node *, const ubii_reply *reply, void *user)
    {
        auto *self = static_cast<DeviceCatcher *>(user);
        self->done = true;
        self->status = ubii_reply_decode(reply, ubii_services_ServiceReply_device_tag,
                                         ubii_devices_Device_fields, &self->device);
    }
};

TEST(Services, DeviceRegistersAndDeregisters)
{
    TestNode node("device-test");
    ASSERT_TRUE(node.wait_ready());
    ubii_devices_Device device = ubii_devices_Device_init_zero;
    std::strcpy(device.name, "libubii test device");
    DeviceCatcher registered;
    ASSERT_EQ(ubii_register_device(node.get(), &device, 0, DeviceCatcher::on_reply, &registered),
              UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return registered.done; }));
    ASSERT_EQ(registered.status, UBII_OK);
    EXPECT_EQ(std::strlen(registered.device.id), 36u);
    EXPECT_STREQ(registered.device.client_id, ubii_node_client_id(node.get()));
    EXPECT_STREQ(registered.device.name, "libubii test device");

    ReplyCatcher removed;
    ASSERT_EQ(ubii_deregister_device(node.get(), registered.device.id, 0, ReplyCatcher::on_reply,
                                     &removed),
              UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return removed.done; }));
    EXPECT_EQ(removed.status, UBII_OK) << removed.title << ": " << removed.message;
    EXPECT_EQ(removed.member, static_cast<uint32_t>(ubii_services_ServiceReply_success_tag));
}

// ---- wrong arguments and states ----------------------------------------------------------------

TEST(Arguments, AreRefusedWithClearStatuses)
{
    TestNode node("arguments-test");
    ASSERT_TRUE(node.poll_until([] { return true; })); // initialised, not started
    EXPECT_EQ(ubii_publish_double(node.get(), "/x", 1.0), UBII_ERR_NOT_CONNECTED);
    EXPECT_EQ(ubii_call_topic(node.get(), UBII_SERVICE_TOPIC_LIST, 0, nullptr, nullptr),
              UBII_ERR_NOT_CONNECTED);
    EXPECT_EQ(ubii_subscribe(node.get(), "", Counter::on_record, nullptr, nullptr),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_subscribe(node.get(), "/x", nullptr, nullptr, nullptr),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_subscribe(node.get(), std::string(300, 'x').c_str(), Counter::on_record, nullptr,
                             nullptr),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_subscribe_regex(node.get(), "(?=x)", Counter::on_record, nullptr, nullptr),
              UBII_ERR_UNSUPPORTED);
    EXPECT_EQ(ubii_subscribe_regex(node.get(), "a(", Counter::on_record, nullptr, nullptr),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_unsubscribe(node.get(), 12345), UBII_ERR_NOT_FOUND);
    for (int i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        ASSERT_EQ(ubii_subscribe(node.get(), ("/t" + std::to_string(i)).c_str(), Counter::on_record,
                                 nullptr, nullptr),
                  UBII_OK);
    }
    EXPECT_EQ(ubii_subscribe(node.get(), "/one-too-many", Counter::on_record, nullptr, nullptr),
              UBII_ERR_FULL);

    ubii_node other;
    ubii_config config;
    ubii_config_init(&config);
    EXPECT_EQ(ubii_node_init(&other, sizeof other - 1, &config, ubii_port{}),
              UBII_ERR_INVALID_ARGUMENT);
    config.service_url = "no-scheme";
    EXPECT_EQ(ubii_node_init(&other, sizeof other, &config, ubii_port{}),
              UBII_ERR_INVALID_ARGUMENT);
}

TEST(Arguments, UnsupportedUrlSchemeFailsAtStart)
{
    TestNode node("scheme-test", "tcp://127.0.0.1:1", "gopher://127.0.0.1:1");
    ASSERT_TRUE(node.poll_until([] { return true; }));
    EXPECT_EQ(node.start(), UBII_ERR_UNSUPPORTED);
    EXPECT_EQ(ubii_node_state(node.get()), UBII_STATE_STOPPED);
}

TEST(Arguments, NoMasterMeansReconnectingNotAHang)
{
    TestNode node("no-master-test", "tcp://127.0.0.1:9", "tcp://127.0.0.1:9");
    node.config().service_timeout_ms = 300;
    ASSERT_TRUE(node.start_and_wait_failed(2, std::chrono::seconds(5)));
    std::vector<ubii_state> expected = {UBII_STATE_CONNECTING, UBII_STATE_RECONNECTING,
                                        UBII_STATE_CONNECTING, UBII_STATE_RECONNECTING,
                                        UBII_STATE_CONNECTING, UBII_STATE_FAILED};
    EXPECT_EQ(node.states(), expected);
}

} // namespace
