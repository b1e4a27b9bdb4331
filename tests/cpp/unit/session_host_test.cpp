// ubii::Node serving sessions on an in-process scripted master (FakePort): what it offers at
// registration, which modules of a start record it runs and how it wires them, what it reports,
// and every way a session can go wrong (docs/PROTOCOL.md §5 states the master's side).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "../session_test_modules.hpp"
#include "fake_port.h"
#include "ubii/messages/topicData/topicData.pb.h"
#include "ubii/ubii.hpp"

using namespace std::chrono_literals;
using ubii::SessionEvent;
using namespace ubii_session_test;

namespace
{

const std::string first_client_id = "11111111-2222-4333-8444-555555555555";
const std::string other_node_id = "99999999-2222-4333-8444-555555555555";
const std::string session_id = "aaaaaaaa-2222-4333-8444-555555555555";

std::atomic<int> created_count{0};

std::unique_ptr<ubii::ProcessingModule> make_doubler()
{
    return std::make_unique<Affine>("doubler", 2, 0, &created_count);
}

ubii::topicData::TopicData session_record(const std::string &topic, const ubii::Session &session)
{
    ubii::topicData::TopicData data;
    data.mutable_topic_data_record()->set_topic(topic);
    *data.mutable_topic_data_record()->mutable_session() = session;
    return data;
}

std::vector<uint8_t> bytes_of(const google::protobuf::MessageLite &message)
{
    const std::string serialized = message.SerializeAsString();
    return std::vector<uint8_t>(serialized.begin(), serialized.end());
}

ubii::ProcessingModuleSpec assigned(const std::string &id, const std::string &name,
                                    const std::string &node_id)
{
    ubii::ProcessingModuleSpec spec;
    spec.set_id(id);
    spec.set_name(name);
    spec.set_node_id(node_id);
    spec.set_session_id(session_id);
    return spec;
}

ubii::IOMapping &mapping_for(ubii::Session &session, const std::string &module_id)
{
    ubii::IOMapping &mapping = *session.add_io_mappings();
    mapping.set_processing_module_id(module_id);
    return mapping;
}

class SessionHostTest : public ::testing::Test
{
  protected:
    SessionHostTest()
    {
        created_count = 0;
        fake.answer = [this](const ubii_services_ServiceRequest &request)
            -> std::optional<std::vector<uint8_t>> {
            const std::string topic = request.topic;
            const ubii::ServiceRequest parsed = last_request();
            if (topic == "/services/server_configuration") {
                ubii::ServiceReply reply;
                reply.mutable_server()->set_id(master_id);
                reply.mutable_server()->set_port_topic_data_zmq("8103");
                return bytes_of(reply);
            }
            if (topic == "/services/client/registration")
                return ubii_test::client_reply(client_id);
            if (topic == "/services/topic_subscription" ||
                topic == "/services/client/deregistration")
                return ubii_test::success_reply();
            if (topic == "/services/processing_module/runtime/add" ||
                topic == "/services/processing_module/runtime/remove") {
                reports.push_back(parsed);
                if (refuse_reports)
                    return ubii_test::error_reply("ProcessingModuleRuntimeAddService",
                                                  "not all processing modules could be verified");
                return ubii_test::success_reply();
            }
            return ubii_test::error_reply("Service request error", "unknown topic: " + topic);
        };
        options.service_url = "tcp://fake:8101";
        options.service_timeout = 1000ms;
        options.is_dedicated_processing_node = true;
        modules.add(make_doubler);
        modules.add([] { return std::make_unique<Broken>("broken"); });
        modules.add([] { return std::make_unique<Gather>("gather"); });
    }

    ubii::ServiceRequest last_request() const
    {
        ubii::ServiceRequest request;
        const auto &bytes = fake.request_bytes.back();
        request.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()));
        return request;
    }

    std::unique_ptr<ubii::Node> serving_node()
    {
        auto node = std::make_unique<ubii::Node>(options, fake.port());
        node->on_error([this](ubii::Status status, std::string_view detail) {
            errors.emplace_back(status, std::string(detail));
        });
        node->on_session_event([this](const SessionEvent &event) { events.push_back(event); });
        node->serve_sessions(modules);
        node->connect(1s);
        return node;
    }

    void deliver(ubii::Node &node, const google::protobuf::MessageLite &topic_data)
    {
        fake.push_topic(bytes_of(topic_data));
        for (int i = 0; i < 5; ++i)
            node.poll(1ms);
    }

    void start(ubii::Node &node, const ubii::Session &session)
    {
        deliver(node, session_record("/info/session/start", session));
    }

    // A session assigning a doubler (x <- /in, y -> /out) to this node, one to another node.
    ubii::Session doubler_session()
    {
        ubii::Session session;
        session.set_id(session_id);
        *session.add_processing_modules() = assigned("pm-1", "doubler", client_id);
        *session.add_processing_modules() = assigned("pm-2", "doubler", other_node_id);
        auto &mapping = mapping_for(session, "pm-1");
        map_input(mapping, "x", "/in");
        map_output(mapping, "y", "/out");
        return session;
    }

    // The doubles the node published on `topic`.
    std::vector<double> published(const std::string &topic) const
    {
        std::vector<double> values;
        for (const auto &sent : fake.topic_sent) {
            ubii::topicData::TopicData data;
            if (data.ParseFromArray(sent.bytes.data(), static_cast<int>(sent.bytes.size())) &&
                data.has_topic_data_record() && data.topic_data_record().topic() == topic)
                values.push_back(data.topic_data_record().double_());
        }
        return values;
    }

    std::vector<SessionEvent::Kind> event_kinds() const
    {
        std::vector<SessionEvent::Kind> kinds;
        for (const auto &event : events)
            kinds.push_back(event.kind);
        return kinds;
    }

    ubii_test::FakePort fake;
    ubii::NodeOptions options;
    ubii::ModuleRegistry modules;
    std::string client_id = first_client_id;
    std::string master_id = "master-1";
    bool refuse_reports = false;
    std::vector<ubii::ServiceRequest> reports;
    std::vector<std::pair<ubii::Status, std::string>> errors;
    std::vector<SessionEvent> events;
};

TEST_F(SessionHostTest, RegistersItsModulesAsADedicatedProcessingNode)
{
    auto node = serving_node();
    ubii::ServiceRequest registration;
    for (std::size_t i = 0; i < fake.requests.size(); ++i) {
        if (std::string(fake.requests[i].topic) == "/services/client/registration")
            registration.ParseFromArray(fake.request_bytes[i].data(),
                                        static_cast<int>(fake.request_bytes[i].size()));
    }
    ASSERT_TRUE(registration.has_client());
    EXPECT_TRUE(registration.client().is_dedicated_processing_node());
    std::vector<std::string> names;
    for (const auto &spec : registration.client().processing_modules()) {
        names.push_back(spec.name());
        EXPECT_EQ(spec.language(), ubii::ProcessingModuleSpec::CPP);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"broken", "doubler", "gather"}));
    EXPECT_TRUE(node->usable(ubii::Behaviour::processing_modules));
}

TEST_F(SessionHostTest, RunsOnlyItsOwnModulesWiredByTheMappingsAndReportsThem)
{
    auto node = serving_node();
    start(*node, doubler_session());

    const auto running = node->session_modules();
    ASSERT_EQ(running.size(), 1u);
    EXPECT_EQ(running[0].id, "pm-1");
    EXPECT_EQ(running[0].session_id, session_id);
    EXPECT_EQ(running[0].status, ubii::ProcessingStatus::processing);
    EXPECT_EQ(node->scheduler().module("pm-1").node_id(), client_id);
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_EQ(reports[0].topic(), "/services/processing_module/runtime/add");
    ASSERT_EQ(reports[0].processing_module_list().elements_size(), 1);
    const auto &reported = reports[0].processing_module_list().elements(0);
    EXPECT_EQ(reported.id(), "pm-1");
    EXPECT_EQ(reported.node_id(), client_id);
    EXPECT_EQ(reported.session_id(), session_id);
    EXPECT_EQ(event_kinds(),
              (std::vector<SessionEvent::Kind>{SessionEvent::Kind::started,
                                               SessionEvent::Kind::confirmed_started}));
    EXPECT_NE(std::find(fake.subscribe_topics.begin(), fake.subscribe_topics.end(), "/in"),
              fake.subscribe_topics.end());

    deliver(*node, session_record("/ignored", {})); // a record on no subscribed topic
    fake.push_topic(ubii_test::double_record("/in", 3));
    node->run_until([&] { return !published("/out").empty(); }, 1s);
    EXPECT_EQ(published("/out"), std::vector<double>{6});
    EXPECT_TRUE(errors.empty()) << errors.front().second;
}

TEST_F(SessionHostTest, ARepeatedStartRecordMakesNoSecondInstance)
{
    auto node = serving_node();
    start(*node, doubler_session());
    start(*node, doubler_session()); // as the master republishes it, or delivers it retained
    EXPECT_EQ(created_count.load(), 1);
    EXPECT_EQ(node->session_modules().size(), 1u);
    EXPECT_EQ(reports.size(), 1u);
    EXPECT_TRUE(errors.empty()) << "a repeat is expected, not an error: " << errors.front().second;
}

TEST_F(SessionHostTest, UnknownAndFailingModulesAreReportedAndTheRestOfTheSessionRuns)
{
    auto node = serving_node();
    ubii::Session session = doubler_session();
    *session.add_processing_modules() = assigned("pm-3", "no-such-module", client_id);
    *session.add_processing_modules() = assigned("pm-4", "broken", client_id);
    start(*node, session);

    ASSERT_EQ(node->session_modules().size(), 1u);
    EXPECT_EQ(node->session_modules()[0].id, "pm-1");
    ASSERT_EQ(reports.size(), 1u);
    ASSERT_EQ(reports[0].processing_module_list().elements_size(), 1)
        << "only modules that run are claimed as started";
    std::map<std::string, std::string> failed;
    for (const auto &event : events) {
        if (event.kind == SessionEvent::Kind::failed)
            failed[event.module_id] = event.detail;
    }
    ASSERT_EQ(failed.size(), 2u);
    EXPECT_NE(failed["pm-3"].find("no processing module named \"no-such-module\""),
              std::string::npos);
    EXPECT_NE(failed["pm-4"].find("no camera attached"), std::string::npos);
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_NE(errors[1].second.find(session_id), std::string::npos);
}

TEST_F(SessionHostTest, AMappingNamingAnUnknownInputIsLeftOutAndTheOthersApply)
{
    auto node = serving_node();
    ubii::Session session = doubler_session();
    auto &mapping = *session.mutable_io_mappings(0);
    auto &wrong = *mapping.add_input_mappings();
    wrong.set_input_name("z");
    wrong.set_topic("/z");
    *mapping.mutable_input_mappings()->Mutable(0)->mutable_input_name() = "x";
    mapping.mutable_input_mappings()->SwapElements(0, 1); // the bad entry first
    start(*node, session);

    ASSERT_EQ(node->session_modules().size(), 1u);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].second.find("no input \"z\""), std::string::npos);
    fake.push_topic(ubii_test::double_record("/in", 4));
    node->run_until([&] { return !published("/out").empty(); }, 1s);
    EXPECT_EQ(published("/out"), std::vector<double>{8});
}

TEST_F(SessionHostTest, AMasterRefusingTheReportIsAnErrorAndTheModuleRunsOn)
{
    refuse_reports = true;
    auto node = serving_node();
    start(*node, doubler_session());
    ASSERT_EQ(node->session_modules().size(), 1u);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].first, ubii::Status::broker);
    EXPECT_NE(errors[0].second.find("could be verified"), std::string::npos) << errors[0].second;
    EXPECT_EQ(event_kinds(), (std::vector<SessionEvent::Kind>{SessionEvent::Kind::started,
                                                              SessionEvent::Kind::failed}));
}

TEST_F(SessionHostTest, AStopRecordDestroysTheSessionsModulesReleasesAndReportsThem)
{
    auto node = serving_node();
    start(*node, doubler_session());
    ubii::Session other;
    other.set_id("some-other-session");
    deliver(*node, session_record("/info/session/stop", other));
    EXPECT_EQ(node->session_modules().size(), 1u) << "another session's stop changes nothing";
    EXPECT_EQ(reports.size(), 1u);

    ubii::Session stopped;
    stopped.set_id(session_id); // the master sends the id alone
    deliver(*node, session_record("/info/session/stop", stopped));
    EXPECT_TRUE(node->session_modules().empty());
    EXPECT_FALSE(node->scheduler().contains("pm-1"));
    EXPECT_NE(std::find(fake.unsubscribe_topics.begin(), fake.unsubscribe_topics.end(), "/in"),
              fake.unsubscribe_topics.end());
    ASSERT_EQ(reports.size(), 2u);
    EXPECT_EQ(reports[1].topic(), "/services/processing_module/runtime/remove");
    ASSERT_EQ(reports[1].processing_module_list().elements_size(), 1);
    EXPECT_EQ(reports[1].processing_module_list().elements(0).id(), "pm-1");
    EXPECT_EQ(reports[1].processing_module_list().elements(0).status(),
              ubii::ProcessingModuleSpec::DESTROYED);
    EXPECT_EQ(events.back().kind, SessionEvent::Kind::confirmed_removed);

    fake.push_topic(ubii_test::double_record("/in", 3));
    for (int i = 0; i < 5; ++i)
        node->poll(1ms);
    EXPECT_TRUE(published("/out").empty());
}

TEST_F(SessionHostTest, MuxInputsFilterByDataTypeAndDemuxOutputsFillTheTopicFormat)
{
    auto node = serving_node();
    ubii::Session session;
    session.set_id(session_id);
    *session.add_processing_modules() = assigned("pm-g", "gather", client_id);
    auto &mapping = mapping_for(session, "pm-g");
    map_mux_input(mapping, "values", "^/sensor/[a-z]+/value$", "double", "/sensor/([a-z]+)/");
    map_output(mapping, "sum", "/sum");
    map_demux_output(mapping, "each", "/copy/{{#0}}", "double");
    start(*node, session);
    ASSERT_EQ(node->session_modules().size(), 1u);
    EXPECT_NE(std::find(fake.subscribe_regexes.begin(), fake.subscribe_regexes.end(),
                        "^/sensor/[a-z]+/value$"),
              fake.subscribe_regexes.end());

    ubii::topicData::TopicData text;
    text.mutable_topic_data_record()->set_topic("/sensor/c/value");
    text.mutable_topic_data_record()->set_string("not a number");
    deliver(*node, text); // another member than data_type: filtered out, not an error
    fake.push_topic(ubii_test::double_record("/sensor/a/value", 1));
    fake.push_topic(ubii_test::double_record("/sensor/b/value", 2));
    node->run_until([&] { return !published("/copy/b").empty(); }, 1s);
    ASSERT_FALSE(published("/sum").empty());
    EXPECT_EQ(published("/sum").back(), 3);
    EXPECT_EQ(published("/copy/a").back(), 1);
    EXPECT_EQ(published("/copy/b"), std::vector<double>{2});
    EXPECT_TRUE(published("/copy/c").empty());
    EXPECT_TRUE(errors.empty()) << errors.front().second;
}

TEST_F(SessionHostTest, AReconnectionKeepsTheModulesAndARestartedMasterEndsThem)
{
    auto node = serving_node();
    start(*node, doubler_session());
    client_id = "22222222-2222-4333-8444-555555555555"; // a reconnection means a new client id
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    node->run_until([&] { return node->state() == ubii::ConnectionState::reconnecting; }, 1s);
    ASSERT_TRUE(node->run_until([&] { return node->ready(); }, 5s));
    for (int i = 0; i < 5; ++i)
        node->poll(1ms);
    ASSERT_EQ(node->session_modules().size(), 1u) << "the same master: the session goes on";
    start(*node, doubler_session()); // the retained start record names the old client id
    EXPECT_EQ(created_count.load(), 1);

    master_id = "master-2";
    fake.set_state(UBII_CHANNEL_TOPIC, UBII_CHANNEL_LOST);
    node->run_until([&] { return node->state() == ubii::ConnectionState::reconnecting; }, 1s);
    ASSERT_TRUE(node->run_until([&] { return node->ready(); }, 5s));
    node->run_until([&] { return node->session_modules().empty(); }, 1s);
    EXPECT_TRUE(node->session_modules().empty());
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back().kind, SessionEvent::Kind::stopped);
    EXPECT_NE(events.back().detail.find("master restarted"), std::string::npos);
}

TEST_F(SessionHostTest, ServingTwiceIsRefused)
{
    auto node = serving_node();
    EXPECT_THROW(node->serve_sessions(modules), ubii::StateError);
}

TEST(ModuleRegistry, RefusesDuplicateNamesAndUnknownOnes)
{
    ubii::ModuleRegistry registry;
    registry.add(make_doubler);
    EXPECT_THROW(registry.add(make_doubler), ubii::InvalidArgument);
    EXPECT_THROW(registry.add([] { return std::unique_ptr<ubii::ProcessingModule>(); }),
                 ubii::InvalidArgument);
    EXPECT_THROW(registry.create("nothing"), ubii::NotFound);
    auto made = registry.create("doubler");
    ASSERT_TRUE(made);
    EXPECT_EQ(made->name(), "doubler");
    EXPECT_EQ(made->status(), ubii::ProcessingStatus::initialized);
}

TEST(DemuxTopic, FillsNumberedPlaceholdersAndRefusesMissingOnes)
{
    EXPECT_EQ(ubii::demux_topic("/hand/{{#0}}/finger/{{#1}}", {"left", "3"}),
              "/hand/left/finger/3");
    EXPECT_EQ(ubii::demux_topic("/plain", {}), "/plain");
    EXPECT_EQ(ubii::demux_topic("/{{#x}}/{{#0}}", {"a"}), "/{{#x}}/a");
    EXPECT_THROW(ubii::demux_topic("/{{#1}}", {"a"}), ubii::InvalidArgument);
}

} // namespace
