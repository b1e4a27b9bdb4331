// ubii::Node on an in-process scripted master (FakePort, simulated time): the preparing step and
// its holds, the exception boundary around the application's callbacks, subscriptions cancelled
// from their own callback or outliving their node, lent records, calls that fail.
#include <gtest/gtest.h>

#include "fake_port.h"
#include "ubii/ubii.hpp"

using namespace std::chrono_literals;
using ubii_test::FakePort;

namespace
{

const std::string client_id = "11111111-2222-4333-8444-555555555555";

class CppNodeWithFakeMaster : public ::testing::Test
{
  protected:
    CppNodeWithFakeMaster()
    {
        fake.answer = [this](const ubii_services_ServiceRequest &request)
            -> std::optional<std::vector<uint8_t>> {
            const std::string topic = request.topic;
            if (topic == "/services/server_configuration")
                return ubii_test::server_reply();
            if (topic == "/services/client/registration")
                return ubii_test::client_reply(client_id);
            if (topic == "/services/topic_subscription" ||
                topic == "/services/client/deregistration")
                return ubii_test::success_reply();
            if (topic == "/services/never")
                return std::nullopt;
            ++unknown_calls;
            return ubii_test::error_reply("Service request error", "unknown topic: " + topic);
        };
        options.service_url = "tcp://fake:8101";
        options.service_timeout = 1000ms;
    }

    // Polls with simulated time until `done` or `rounds` polls.
    template <class Done> bool poll_until(ubii::Node &node, Done done, int rounds = 50)
    {
        for (int i = 0; i < rounds && !done(); ++i)
            node.poll(10ms);
        return done();
    }

    FakePort fake;
    ubii::NodeOptions options;
    int unknown_calls = 0;
};

TEST_F(CppNodeWithFakeMaster, ReachesReadyThroughPreparingAndReportsEveryState)
{
    ubii::Node node(options, fake.port());
    std::vector<ubii::ConnectionState> states;
    node.on_state([&](ubii::ConnectionState, ubii::ConnectionState current, ubii::Status) {
        states.push_back(current);
    });
    node.start();
    ASSERT_TRUE(poll_until(node, [&] { return node.ready(); }));
    using S = ubii::ConnectionState;
    EXPECT_EQ(states,
              (std::vector<S>{S::connecting, S::registering, S::opening, S::preparing, S::ready}));
    EXPECT_EQ(node.client_id(), client_id);
}

TEST_F(CppNodeWithFakeMaster, AHoldOnPreparingDelaysReadyUntilReleased)
{
    ubii::Node node(options, fake.port());
    std::optional<ubii::Hold> hold;
    node.connection().on_enter(ubii::ConnectionState::preparing,
                               [&](ubii::ConnectionTransition &t) { hold.emplace(t.hold()); });
    node.start();
    ASSERT_TRUE(poll_until(node, [&] { return node.state() == ubii::ConnectionState::preparing; }));
    for (int i = 0; i < 10; ++i)
        node.poll(10ms);
    EXPECT_EQ(node.state(), ubii::ConnectionState::preparing);
    EXPECT_FALSE(node.usable(ubii::Behaviour::publishing));
    EXPECT_EQ(node.try_publish("/early", 1.0), ubii::Status::ok)
        << "the core is ready: publishing works while the node prepares";
    hold->release();
    node.poll();
    EXPECT_TRUE(node.ready());
}

TEST_F(CppNodeWithFakeMaster, ACallbackThatThrowsIsReportedCountedAndTheNextRecordStillArrives)
{
    ubii::Node node(options, fake.port());
    std::vector<std::pair<ubii::Status, std::string>> errors;
    node.on_error([&](ubii::Status status, std::string_view detail) {
        errors.emplace_back(status, std::string(detail));
    });
    node.connect(1s);
    std::vector<double> seen;
    auto subscription = node.subscribe("/in", [&](const ubii::Record &record) {
        seen.push_back(record.as<double>());
        if (seen.size() == 1)
            throw std::runtime_error("the application failed");
    });
    fake.push_topic(ubii_test::double_record("/in", 1.0));
    fake.push_topic(ubii_test::double_record("/in", 2.0));
    node.poll();
    node.poll();
    EXPECT_EQ(seen, (std::vector<double>{1.0, 2.0}));
    EXPECT_EQ(node.stats().callback_errors, 1u);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].first, ubii::Status::callback_threw);
    EXPECT_EQ(errors[0].second, "the subscription to /in: the application failed");
}

TEST_F(CppNodeWithFakeMaster, ATypedSubscriptionCountsAndReportsRecordsOfAnotherType)
{
    ubii::Node node(options, fake.port());
    std::vector<ubii::Status> errors;
    node.on_error([&](ubii::Status status, std::string_view) { errors.push_back(status); });
    node.connect(1s);
    int vectors = 0;
    auto subscription = node.subscribe<ubii::Vector3>(
        "/in", [&](const ubii::Vector3 &, const ubii::RecordInfo &) { ++vectors; });
    fake.push_topic(ubii_test::double_record("/in", 1.0));
    node.poll();
    EXPECT_EQ(vectors, 0);
    EXPECT_EQ(node.stats().type_mismatches, 1u);
    EXPECT_EQ(errors, (std::vector<ubii::Status>{ubii::Status::wrong_type}));
}

TEST_F(CppNodeWithFakeMaster, ASubscriptionCancelledInItsOwnCallbackGetsNothingMore)
{
    ubii::Node node(options, fake.port());
    node.connect(1s);
    int count = 0;
    ubii::Subscription subscription;
    subscription = node.subscribe("/in", [&](const ubii::Record &) {
        ++count;
        subscription.cancel(); // frees nothing the running callback still uses
    });
    ASSERT_TRUE(poll_until(node, [&] { return !fake.subscribe_topics.empty(); }));
    fake.push_topic(ubii_test::double_record("/in", 1.0));
    fake.push_topic(ubii_test::double_record("/in", 2.0));
    node.poll();
    node.poll();
    EXPECT_EQ(count, 1);
    EXPECT_FALSE(subscription.active());
    poll_until(node, [&] { return !fake.unsubscribe_topics.empty(); });
    EXPECT_EQ(fake.unsubscribe_topics, (std::vector<std::string>{"/in"}));
}

TEST_F(CppNodeWithFakeMaster, ASubscriptionOutlivingItsNodeIsHarmless)
{
    ubii::Subscription survivor;
    {
        ubii::Node node(options, fake.port());
        node.connect(1s);
        survivor = node.subscribe("/in", [](const ubii::Record &) {});
        EXPECT_TRUE(survivor.active());
    }
    EXPECT_FALSE(survivor.active());
    survivor.cancel();
}

TEST_F(CppNodeWithFakeMaster, AMovedNodeKeepsItsSubscriptions)
{
    ubii::Node first(options, fake.port());
    first.connect(1s);
    int count = 0;
    auto subscription = first.subscribe("/in", [&](const ubii::Record &) { ++count; });
    ubii::Node second = std::move(first);
    fake.push_topic(ubii_test::double_record("/in", 1.0));
    second.poll();
    EXPECT_EQ(count, 1);
    EXPECT_TRUE(subscription.active());
}

TEST_F(CppNodeWithFakeMaster, LentRecordsAreCopiedOutWhole)
{
    ubii::Node node(options, fake.port());
    node.connect(1s);
    std::optional<ubii::Record> kept;
    bool was_lent = false;
    auto subscription = node.subscribe("/in", [&](const ubii::Record &record) {
        was_lent = record.lent();
        kept = record;
    });
    fake.push_topic(ubii_test::double_record("/in", 42.0));
    node.poll();
    fake.push_topic(ubii_test::double_record("/other", 1.0)); // the receive buffer is reused
    node.poll();
    ASSERT_TRUE(kept.has_value());
    EXPECT_TRUE(was_lent);
    EXPECT_FALSE(kept->lent());
    EXPECT_EQ(kept->topic(), "/in");
    EXPECT_EQ(kept->as<double>(), 42.0);
}

TEST_F(CppNodeWithFakeMaster, PublishingBeforeReadyThrowsOrReports)
{
    ubii::Node node(options, fake.port());
    EXPECT_THROW(node.publish("/out", 1.0), ubii::NotConnected);
    EXPECT_EQ(node.try_publish("/out", 1.0), ubii::Status::not_connected);
    node.connect(1s);
    EXPECT_EQ(node.try_publish(std::string(300, 'x'), 1.0), ubii::Status::invalid_argument);
    EXPECT_EQ(node.try_publish("/out", ubii::Value()), ubii::Status::invalid_argument);
    node.publish("/out", 1.0);
    node.publish("/out", ubii::vector3(1, 2, 3));
    node.publish(ubii::Record(
        "/out", ubii::Value(ubii::RecordType::QUATERNION_LIST, ubii::quaternion(0, 0, 0, 1))));
    EXPECT_EQ(node.stats().records_published, 3u);
}

TEST_F(CppNodeWithFakeMaster, CallsResolveWithTheMastersErrorOrATimeout)
{
    ubii::Node node(options, fake.port());
    node.connect(1s);
    ubii::ServiceRequest request;
    request.set_topic("/services/unknown");
    auto refused = node.call(request);
    request.set_topic("/services/never");
    auto unanswered = node.call(request, 300ms);
    std::optional<ubii::Status> continuation;
    unanswered.then(
        [&](const ubii::Result<ubii::ServiceReply> &result) { continuation = result.status(); });
    ASSERT_TRUE(poll_until(node, [&] { return refused.done() && unanswered.done(); }));
    EXPECT_EQ(refused.result().status(), ubii::Status::broker);
    try {
        refused.get();
        ADD_FAILURE() << "an error reply resolved as a reply";
    } catch (const ubii::ServiceError &error) {
        EXPECT_EQ(error.title(), "Service request error");
        EXPECT_EQ(error.message(), "unknown topic: /services/unknown");
    }
    EXPECT_THROW(unanswered.get(), ubii::Timeout);
    EXPECT_EQ(continuation, ubii::Status::timeout);
}

TEST_F(CppNodeWithFakeMaster, PollingFromInsideACallbackIsAStateError)
{
    ubii::Node node(options, fake.port());
    node.connect(1s);
    std::vector<ubii::Status> errors;
    node.on_error([&](ubii::Status status, std::string_view) { errors.push_back(status); });
    auto subscription = node.subscribe("/in", [&](const ubii::Record &) { node.poll(); });
    fake.push_topic(ubii_test::double_record("/in", 1.0));
    node.poll();
    EXPECT_EQ(errors, (std::vector<ubii::Status>{ubii::Status::callback_threw}));
}

TEST_F(CppNodeWithFakeMaster, TheDestructorDeregistersAndRunsNoApplicationHandler)
{
    bool handler_ran_in_destructor = false;
    bool destroying = false;
    {
        ubii::Node node(options, fake.port());
        node.connect(1s);
        node.on_state([&](ubii::ConnectionState, ubii::ConnectionState, ubii::Status) {
            handler_ran_in_destructor |= destroying;
        });
        destroying = true;
    }
    EXPECT_FALSE(handler_ran_in_destructor);
    ASSERT_FALSE(fake.requests.empty());
    EXPECT_EQ(std::string(fake.requests.back().topic), "/services/client/deregistration");
}

} // namespace
