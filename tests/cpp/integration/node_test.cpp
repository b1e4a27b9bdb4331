// ubii::Node against the real npm master: RAII subscriptions and nodes, service helpers with
// error replies and timeouts, behaviours.
#include <gtest/gtest.h>

#include "cpp_test_support.hpp"
#include "loopback.h"
#include "test_node.h"

using namespace std::chrono_literals;
using ubii_cpp_test::options_for;

namespace
{

// A destroyed Subscription makes the master stop forwarding: counted on the node's own topic
// connection, below every subscription.
TEST(NodeSubscriptions, ADestroyedSubscriptionStopsTheMastersForwarding)
{
    ubii::Node publisher(options_for("cpp-raii-publisher"));
    publisher.connect(10s);
    ubii_cpp_test::CountingPort counting;
    ubii::Node node(options_for("cpp-raii-subscriber"), counting.get());
    node.connect(10s);
    const std::string topic = ubii_test::unique_topic("/cpp-raii");

    int delivered = 0;
    {
        ubii::Subscription subscription =
            node.subscribe<double>(topic, [&](double, const ubii::RecordInfo &) { ++delivered; });
        ASSERT_TRUE(subscription.active());
        ASSERT_TRUE(node.run_until(
            [&] {
                publisher.publish(topic, 1.0);
                publisher.poll();
                return delivered > 0;
            },
            10s));
    }
    node.run_for(300ms); // the unsubscription reaches the master; records already sent drain
    const auto forwarded_before = counting.topic_messages();
    const int delivered_before = delivered;
    for (int i = 0; i < 50; ++i) {
        publisher.publish(topic, 2.0);
        publisher.poll();
        node.poll(10ms);
    }
    node.run_for(200ms);
    EXPECT_EQ(counting.topic_messages(), forwarded_before) << "the master still forwards " << topic;
    EXPECT_EQ(delivered, delivered_before);
}

// cancel() and release(): a released subscription lives on with the node; a moved one is the same
// subscription.
TEST(NodeSubscriptions, MovedAndReleasedSubscriptionsKeepDelivering)
{
    ubii::Node node(options_for("cpp-moved-subscriptions"));
    node.connect(10s);
    const std::string topic = ubii_test::unique_topic("/cpp-moved");
    int count = 0;
    ubii::Subscription moved;
    {
        ubii::Subscription original = node.subscribe(topic, [&](const ubii::Record &) { ++count; });
        moved = std::move(original);
        EXPECT_FALSE(original.active()); // NOLINT(bugprone-use-after-move): moved-from is empty
    }
    ASSERT_TRUE(moved.active());
    ASSERT_TRUE(node.run_until(
        [&] {
            node.publish(topic, 1);
            node.poll(20ms);
            return count > 0;
        },
        10s));
    moved.release();
    EXPECT_FALSE(moved.active());
    const int before = count;
    ASSERT_TRUE(node.run_until(
        [&] {
            node.publish(topic, 2);
            node.poll(20ms);
            return count > before;
        },
        10s))
        << "a released subscription must keep delivering";
}

// A TopicSubscription request on behalf of `client_id`: the master refuses it for a client it
// does not know.
ubii::ServiceRequest subscription_request_for(const std::string &client_id)
{
    ubii::ServiceRequest request;
    request.set_topic("/services/topic_subscription");
    request.mutable_topic_subscription()->set_client_id(client_id);
    return request;
}

TEST(NodeLifetime, ADestroyedNodeLeavesNoClientRegistered)
{
    ubii::Node witness(options_for("cpp-lifetime-witness"));
    witness.connect(10s);
    std::string old_id;
    {
        ubii::Node node(options_for("cpp-lifetime"));
        node.connect(10s);
        old_id = node.client_id();
        ASSERT_EQ(old_id.size(), 36u);
        // Known while it lives:
        EXPECT_NO_THROW(witness.wait(witness.call(subscription_request_for(old_id)), 5s));
        auto subscription = node.subscribe("/cpp-lifetime/anything", [](const ubii::Record &) {});
        node.run_for(100ms);
    }
    try {
        witness.wait(witness.call(subscription_request_for(old_id)), 5s);
        ADD_FAILURE() << old_id << " is still registered after its node was destroyed";
    } catch (const ubii::ServiceError &error) {
        EXPECT_NE(error.message().find(old_id), std::string::npos) << error.what();
    }
}

TEST(NodeServices, TypedHelpersReturnTheMastersAnswers)
{
    ubii::Node node(options_for("cpp-services"));
    node.connect(10s);
    const ubii::Server server = node.wait(node.master().server_configuration(), 5s);
    EXPECT_EQ(server.port_topic_data_zmq(), std::to_string(ubii_test::port_base() + 2));
    EXPECT_EQ(server.port_topic_data_ws(), std::to_string(ubii_test::port_base() + 3));

    const ubii::ServiceList services = node.wait(node.master().services(), 5s);
    bool lists_registration = false;
    for (const auto &service : services.elements())
        lists_registration |= service.topic() == "/services/client/registration";
    EXPECT_TRUE(lists_registration) << services.elements_size() << " services";

    const std::string topic = ubii_test::unique_topic("/cpp-listed");
    node.publish(topic, 1.0);
    node.run_for(200ms);
    const ubii::StringList topics = node.wait(node.master().topics(), 5s);
    EXPECT_NE(std::find(topics.elements().begin(), topics.elements().end(), topic),
              topics.elements().end());

    EXPECT_NO_THROW(node.wait(node.sessions().list(), 5s));
}

TEST(NodeServices, DevicesWithComponentsAreRegisteredAndDeregistered)
{
    ubii::Node node(options_for("cpp-devices"));
    node.connect(10s);
    ubii::Device device;
    device.set_name("libubii C++ test device");
    device.set_device_type(ubii::Device::PARTICIPANT);
    auto *component = device.add_components();
    component->set_topic(ubii_test::unique_topic("/cpp-device/out"));
    component->set_message_format("double");
    component->set_io_type(ubii::Component::PUBLISHER);
    const ubii::Device registered = node.wait(node.master().register_device(device), 5s);
    EXPECT_EQ(registered.id().size(), 36u);
    EXPECT_EQ(registered.client_id(), node.client_id());
    ASSERT_EQ(registered.components_size(), 1);
    EXPECT_EQ(registered.components(0).topic(), component->topic());

    EXPECT_NO_THROW(node.wait(node.master().deregister_device(registered.id()), 5s));
}

TEST(NodeServices, AnErrorReplyIsAServiceErrorWithTheMastersWords)
{
    ubii::Node node(options_for("cpp-service-error"));
    node.connect(10s);
    ubii::ServiceRequest request;
    request.set_topic("/services/no/such/service");
    auto call = node.call(request);
    try {
        node.wait(call, 5s);
        ADD_FAILURE() << "an unknown service was answered";
    } catch (const ubii::ServiceError &error) {
        EXPECT_EQ(error.service(), "/services/no/such/service");
        EXPECT_FALSE(error.title().empty());
        EXPECT_NE(std::string(error.what()).find(error.title()), std::string::npos);
    }
    ASSERT_TRUE(call.done());
    EXPECT_FALSE(call.result().ok());
    EXPECT_EQ(call.result().status(), ubii::Status::broker);

    // The callback form sees the same outcome.
    std::optional<ubii::Status> seen;
    node.master().clients().then(
        [&](const ubii::Result<ubii::ClientList> &clients) { seen = clients.status(); });
    ASSERT_TRUE(node.run_until([&] { return seen.has_value(); }, 5s));
    // The npm 0.4.0 master has no client list service: an error reply, not a list.
    EXPECT_EQ(*seen, ubii::Status::broker);
}

// A reply that never reaches the node (the port loses it, though the master answered): the call
// resolves with ubii::Timeout after its own timeout, and the node goes on. Waiting less than that
// throws ubii::Timeout and leaves the call pending.
TEST(NodeServices, AnUnansweredCallTimesOut)
{
    ubii_cpp_test::CountingPort port;
    ubii::Node node(options_for("cpp-service-timeout"), port.get());
    node.connect(10s);
    port.lose_service_replies(1);
    auto lost = node.master().with_timeout(300ms).server_configuration();
    try {
        node.wait(lost, 5s);
        ADD_FAILURE() << "a lost reply was answered";
    } catch (const ubii::Timeout &error) {
        EXPECT_NE(std::string(error.what()).find("/services/server_configuration"),
                  std::string::npos);
        EXPECT_NE(std::string(error.what()).find("300 ms"), std::string::npos) << error.what();
    }
    EXPECT_EQ(node.stats().service_timeouts, 1u);
    EXPECT_NO_THROW(node.wait(node.master().server_configuration(), 5s));

    port.lose_service_replies(1);
    auto pending = node.master().with_timeout(500ms).server_configuration();
    EXPECT_THROW(node.wait(pending, 100ms), ubii::Timeout);
    EXPECT_FALSE(pending.done());
    EXPECT_THROW(node.wait(pending, 5s), ubii::Timeout); // now its own timeout
    EXPECT_TRUE(pending.done());
}

TEST(NodeBehaviours, WhenUsableRunsOnceTheNodeIsReady)
{
    ubii::Node node(options_for("cpp-behaviours"));
    EXPECT_TRUE(node.implements(ubii::Behaviour::publishing));
    EXPECT_TRUE(node.implements(ubii::Behaviour::services));
    EXPECT_TRUE(node.implements(ubii::Behaviour::processing_modules));
    EXPECT_FALSE(node.usable(ubii::Behaviour::publishing));

    int runs = 0;
    bool was_ready = false;
    node.when_usable(ubii::Behaviour::publishing, [&] {
        ++runs;
        was_ready = node.ready();
    });
    node.start();
    ASSERT_TRUE(node.wait_usable(ubii::Behaviour::services, 10s));
    node.run_for(100ms);
    EXPECT_EQ(runs, 1);
    EXPECT_TRUE(was_ready);
    EXPECT_FALSE(node.usable(ubii::Behaviour::processing_modules))
        << "ready, but it serves no sessions (Node::serve_sessions)";
    // Usable now: the action runs at the next poll, once.
    node.when_usable(ubii::Behaviour::services, [&] { ++runs; });
    node.poll();
    node.poll();
    EXPECT_EQ(runs, 2);
}

TEST(NodeLifecycle, ConnectingToNothingThrowsTimeoutWithTheTransportsWord)
{
    ubii::NodeOptions options = options_for("cpp-nowhere");
    options.service_url = "tcp://127.0.0.1:9"; // nothing listens there
    ubii::Node node(options);
    EXPECT_THROW(node.connect(500ms), ubii::Timeout);
    EXPECT_THROW(node.publish("/cpp/nowhere", 1.0), ubii::NotConnected);
    EXPECT_EQ(node.try_publish("/cpp/nowhere", 1.0), ubii::Status::not_connected);
    EXPECT_THROW(node.call(ubii::ServiceRequest()), ubii::Error);
}

} // namespace
