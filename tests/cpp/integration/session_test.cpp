// Sessions against a master that assigns processing modules to nodes: the current master, run
// from a checkout (scripts/current-master.sh; the npm 0.4.0 master runs every session module
// itself and tells nodes nothing: docs/PROTOCOL.md §6). The official Node.js node is the other
// party: it publishes the inputs, receives the outputs, and runs a JavaScript module of its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>

#include "../session_test_modules.hpp"
#include "child_process.h"
#include "cpp_test_support.hpp"
#include "test_node.h"

using namespace std::chrono_literals;
using ubii::SessionEvent;
using namespace ubii_session_test;

namespace
{

std::atomic<int> broken_created{0};

std::unique_ptr<ubii::ProcessingModule> make_doubler()
{
    return std::make_unique<Affine>("libubii_doubler", 2, 0);
}

std::unique_ptr<ubii::ProcessingModule> make_offset()
{
    return std::make_unique<Affine>("libubii_offset", 1, 1000);
}

// A working directory of the Node.js peer's own (its module database lives there).
std::string peer_dir(const std::string &name)
{
    const char *base = std::getenv("UBII_SESSION_PEER_DIR");
    const std::string dir = std::string(base != nullptr ? base : "/tmp") + "/" + name;
    std::filesystem::create_directories(dir);
    return dir;
}

// A session spec as a client writes it: modules by name, mappings by module name (the master
// fills in the ids, docs/PROTOCOL.md §5.1).
struct SessionSpec {
    ubii::Session session;

    explicit SessionSpec(const std::string &name)
    {
        session.set_name(name);
    }
    // The module's mapping. (A mapping without input entries makes the current master fail the
    // start with a TypeError: give a module without inputs none.)
    ubii::IOMapping &module(const std::string &name)
    {
        add_module(name);
        ubii::IOMapping &mapping = *session.add_io_mappings();
        mapping.set_processing_module_name(name);
        return mapping;
    }
    void add_module(const std::string &name)
    {
        session.add_processing_modules()->set_name(name);
    }
};

class SessionTest : public ::testing::Test
{
  protected:
    // A dedicated processing node offering `modules`, recording its events and errors.
    struct ServingNode {
        std::unique_ptr<ubii::Node> node;
        std::vector<SessionEvent> events;
        std::vector<std::string> errors;

        int count(SessionEvent::Kind kind) const
        {
            return static_cast<int>(std::count_if(
                events.begin(), events.end(), [kind](const auto &e) { return e.kind == kind; }));
        }
    };

    std::unique_ptr<ServingNode> serving(const std::string &name, ubii::ModuleRegistry modules)
    {
        auto serving = std::make_unique<ServingNode>();
        ubii::NodeOptions options = ubii_cpp_test::options_for(name);
        options.is_dedicated_processing_node = true;
        serving->node = std::make_unique<ubii::Node>(options);
        ServingNode *raw = serving.get();
        serving->node->on_session_event([raw](const SessionEvent &e) { raw->events.push_back(e); });
        serving->node->on_error(
            [raw](ubii::Status, std::string_view detail) { raw->errors.emplace_back(detail); });
        serving->node->serve_sessions(std::move(modules));
        serving->node->connect(10s);
        return serving;
    }

    void SetUp() override
    {
        client = std::make_unique<ubii::Node>(ubii_cpp_test::options_for("session-client"));
        client->connect(10s);
    }

    // Polls every node given (and the client) until `done` or `timeout`.
    bool poll_all(const std::vector<ubii::Node *> &nodes, const std::function<bool()> &done,
                  std::chrono::milliseconds timeout)
    {
        const auto until = std::chrono::steady_clock::now() + timeout;
        while (!done()) {
            if (std::chrono::steady_clock::now() > until)
                return false;
            client->poll(2ms);
            for (ubii::Node *node : nodes)
                node->poll(2ms);
        }
        return true;
    }

    ubii::Session start(const std::vector<ubii::Node *> &nodes, const ubii::Session &spec)
    {
        auto call = client->sessions().start(spec);
        EXPECT_TRUE(poll_all(
            nodes, [&] { return call.done(); }, 10s));
        return call.get();
    }

    ubii::sessions::SessionStatus status_of(const std::vector<ubii::Node *> &nodes,
                                            const std::string &id)
    {
        auto call = client->sessions().get(id);
        poll_all(
            nodes, [&] { return call.done(); }, 5s);
        return call.get().status();
    }

    bool reaches(const std::vector<ubii::Node *> &nodes, const std::string &id,
                 ubii::sessions::SessionStatus status)
    {
        const auto until = std::chrono::steady_clock::now() + 15s;
        while (std::chrono::steady_clock::now() < until) {
            if (status_of(nodes, id) == status)
                return true;
            poll_all(
                nodes, [] { return false; }, 100ms);
        }
        return false;
    }

    std::unique_ptr<ubii::Node> client;
};

TEST_F(SessionTest, ALibubiiModuleServesTheNodejsNodeAndStopsCleanly)
{
    ubii::ModuleRegistry modules;
    modules.add(make_doubler);
    auto worker = serving("libubii-worker", std::move(modules));
    ubii_test::ChildProcess peer({"node", UBII_SESSION_PEER, UBII_NODEJS_CLIENT,
                                  ubii_test::service_url(), ubii_test::topic_zmq_url(),
                                  peer_dir("plain"), "none", "/s1/in", "/s1/out"});
    ASSERT_TRUE(peer.started());

    SessionSpec spec("one-libubii-module");
    auto &doubler = spec.module("libubii_doubler");
    map_input(doubler, "x", "/s1/in");
    map_output(doubler, "y", "/s1/out");
    const std::vector<ubii::Node *> nodes{worker->node.get()};
    const ubii::Session session = start(nodes, spec.session);
    ASSERT_FALSE(session.id().empty());

    ASSERT_TRUE(poll_all(
        nodes, [&] { return worker->count(SessionEvent::Kind::confirmed_started) == 1; }, 10s))
        << (worker->errors.empty() ? "" : worker->errors.front());
    EXPECT_TRUE(reaches(nodes, session.id(), ubii::sessions::RUNNING))
        << "the master counts the report";
    ASSERT_EQ(worker->node->session_modules().size(), 1u);
    EXPECT_EQ(worker->node->session_modules()[0].session_id, session.id());

    // The Node.js node publishes 1, 2, 3, ...; twice each comes back.
    std::vector<double> got;
    ASSERT_TRUE(poll_all(
        nodes,
        [&] {
            for (const std::string &line : peer.lines())
                if (line.rfind("PEER got ", 0) == 0)
                    got.push_back(std::stod(line.substr(9)));
            peer.lines().clear();
            return got.size() >= 3;
        },
        10s));
    for (double value : got)
        EXPECT_EQ(static_cast<long long>(value) % 2, 0) << value;

    auto stopped = client->sessions().stop(session.id());
    ASSERT_TRUE(poll_all(
        nodes, [&] { return stopped.done(); }, 5s));
    EXPECT_EQ(stopped.get().id(), session.id())
        << "the master's error reply to stop is not an error";
    ASSERT_TRUE(poll_all(
        nodes, [&] { return worker->count(SessionEvent::Kind::confirmed_removed) == 1; }, 10s));
    EXPECT_TRUE(worker->node->session_modules().empty());
    EXPECT_TRUE(reaches(nodes, session.id(), ubii::sessions::STOPPED));

    // The subscription of the module's input is released at the master: nothing more arrives.
    poll_all(
        nodes, [] { return false; }, 300ms);
    const auto received = worker->node->stats().records_received;
    poll_all(
        nodes, [] { return false; }, 600ms); // the Node.js node goes on publishing /s1/in
    EXPECT_EQ(worker->node->stats().records_received, received);
    EXPECT_TRUE(worker->errors.empty()) << worker->errors.front();
    peer.stop(SIGTERM, 3s);
}

TEST_F(SessionTest, ANodejsModuleFeedsALibubiiModuleInOneSession)
{
    ubii::ModuleRegistry modules;
    modules.add(make_doubler);
    auto worker = serving("libubii-chain", std::move(modules));
    ubii_test::ChildProcess peer({"node", UBII_SESSION_PEER, UBII_NODEJS_CLIENT,
                                  ubii_test::service_url(), ubii_test::topic_zmq_url(),
                                  peer_dir("chain"), "js_negate", "/c/in", "/c/out"});
    const std::vector<ubii::Node *> nodes{worker->node.get()};
    ASSERT_TRUE(poll_all(
        nodes,
        [&] {
            return std::any_of(
                peer.lines().begin(), peer.lines().end(),
                [](const std::string &line) { return line.rfind("PEER ready", 0) == 0; });
        },
        15s))
        << [&] {
               std::string all;
               for (const std::string &line : peer.lines())
                   all += line + "\n";
               return all;
           }();

    SessionSpec spec("chain-across-languages");
    auto &negate = spec.module("js_negate"); // run by the Node.js node
    map_input(negate, "x", "/c/in");
    map_output(negate, "y", "/c/mid");
    auto &doubler = spec.module("libubii_doubler");
    map_input(doubler, "x", "/c/mid");
    map_output(doubler, "y", "/c/out");
    const ubii::Session session = start(nodes, spec.session);
    EXPECT_TRUE(reaches(nodes, session.id(), ubii::sessions::RUNNING));

    std::vector<double> got;
    ASSERT_TRUE(poll_all(
        nodes,
        [&] {
            for (const std::string &line : peer.lines())
                if (line.rfind("PEER got ", 0) == 0)
                    got.push_back(std::stod(line.substr(9)));
            peer.lines().clear();
            return got.size() >= 3;
        },
        15s))
        << "nothing came back through js_negate and libubii_doubler";
    for (double value : got)
        EXPECT_TRUE(value < 0 && static_cast<long long>(value) % 2 == 0) << value;
    client->sessions().stop(session.id());
    poll_all(
        nodes, [&] { return worker->node->session_modules().empty(); }, 10s);
    peer.stop(SIGTERM, 3s);
}

TEST_F(SessionTest, TwoDedicatedNodesEachRunTheModuleTheyOffer)
{
    ubii::ModuleRegistry first_modules, second_modules;
    first_modules.add(make_doubler);
    second_modules.add(make_offset);
    auto first = serving("libubii-first", std::move(first_modules));
    auto second = serving("libubii-second", std::move(second_modules));
    const std::vector<ubii::Node *> nodes{first->node.get(), second->node.get()};

    SessionSpec spec("two-nodes");
    auto &doubler = spec.module("libubii_doubler");
    map_input(doubler, "x", "/two/in");
    map_output(doubler, "y", "/two/mid");
    auto &offset = spec.module("libubii_offset");
    map_input(offset, "x", "/two/mid");
    map_output(offset, "y", "/two/out");
    const ubii::Session session = start(nodes, spec.session);
    EXPECT_TRUE(reaches(nodes, session.id(), ubii::sessions::RUNNING));
    ASSERT_EQ(first->node->session_modules().size(), 1u);
    ASSERT_EQ(second->node->session_modules().size(), 1u);
    EXPECT_EQ(first->node->session_modules()[0].name, "libubii_doubler");
    EXPECT_EQ(second->node->session_modules()[0].name, "libubii_offset");

    std::vector<double> out;
    auto subscription = client->subscribe<double>(
        "/two/out", [&](double value, const ubii::RecordInfo &) { out.push_back(value); });
    poll_all(
        nodes, [] { return false; }, 300ms);
    ASSERT_TRUE(poll_all(
        nodes,
        [&] {
            client->publish("/two/in", 21.0);
            return !out.empty();
        },
        10s));
    EXPECT_EQ(out.front(), 1042);
    client->sessions().stop(session.id());
    EXPECT_TRUE(reaches(nodes, session.id(), ubii::sessions::STOPPED));
}

TEST_F(SessionTest, MuxInputsAndDemuxOutputsThroughTheMaster)
{
    ubii::ModuleRegistry modules;
    modules.add([] { return std::make_unique<Gather>("libubii_gather"); });
    auto worker = serving("libubii-mux", std::move(modules));
    const std::vector<ubii::Node *> nodes{worker->node.get()};

    SessionSpec spec("mux-demux");
    auto &gather = spec.module("libubii_gather");
    map_mux_input(gather, "values", "^/m/sensor/[a-z]+/value$", "double", "/sensor/([a-z]+)/");
    map_output(gather, "sum", "/m/sum");
    map_demux_output(gather, "each", "/m/copy/{{#0}}", "double");
    const ubii::Session session = start(nodes, spec.session);
    EXPECT_TRUE(reaches(nodes, session.id(), ubii::sessions::RUNNING));

    std::map<std::string, double> copies;
    double sum = 0;
    auto copies_sub = client->subscribe_regex<double>(
        "^/m/copy/", [&](double value, const ubii::RecordInfo &info) {
            copies[std::string(info.topic)] = value;
        });
    auto sum_sub = client->subscribe<double>(
        "/m/sum", [&](double value, const ubii::RecordInfo &) { sum = value; });
    poll_all(
        nodes, [] { return false; }, 300ms);
    ASSERT_TRUE(poll_all(
        nodes,
        [&] {
            client->publish("/m/sensor/a/value", 1.0);
            client->publish("/m/sensor/b/value", 20.0);
            client->publish("/m/sensor/c/value", 300.0);
            client->publish("/m/sensor/d/value", "not a number"); // filtered by data_type
            return copies.size() >= 3 && sum == 321;
        },
        10s))
        << "sum " << sum << ", " << copies.size() << " copies";
    EXPECT_EQ(copies["/m/copy/a"], 1);
    EXPECT_EQ(copies["/m/copy/c"], 300);
    EXPECT_EQ(copies.count("/m/copy/d"), 0u);
    client->sessions().stop(session.id());
    poll_all(
        nodes, [&] { return worker->node->session_modules().empty(); }, 10s);
    EXPECT_TRUE(worker->errors.empty()) << worker->errors.front();
}

TEST_F(SessionTest, BadModulesRepeatedStartsAndUnknownStopsAreHandled)
{
    ubii::ModuleRegistry modules;
    modules.add(make_doubler);
    modules.add([] { return std::make_unique<Broken>("libubii_broken", &broken_created); });
    auto worker = serving("libubii-bad", std::move(modules));
    const std::vector<ubii::Node *> nodes{worker->node.get()};

    SessionSpec spec("bad-cases");
    auto &doubler = spec.module("libubii_doubler");
    map_input(doubler, "x", "/bad/in");
    map_output(doubler, "y", "/bad/out");
    spec.add_module("libubii_broken");
    // A module the spec assigns to this node by id although the node does not offer it.
    spec.session.add_processing_modules()->set_name("no_such_module");
    spec.session.mutable_processing_modules(2)->set_node_id(worker->node->client_id());
    const ubii::Session session = start(nodes, spec.session);
    ASSERT_TRUE(poll_all(
        nodes, [&] { return worker->count(SessionEvent::Kind::failed) >= 2; }, 10s));
    poll_all(
        nodes, [] { return false; }, 500ms);
    EXPECT_EQ(broken_created.load(), 1);
    ASSERT_EQ(worker->node->session_modules().size(), 1u) << "the rest of the session runs";
    EXPECT_EQ(worker->node->session_modules()[0].name, "libubii_doubler");
    EXPECT_EQ(worker->count(SessionEvent::Kind::confirmed_started), 1);
    EXPECT_NE(status_of(nodes, session.id()), ubii::sessions::RUNNING)
        << "the modules that failed were not claimed as started";

    // Started again: the master republishes the start record; nothing runs twice.
    const auto errors_before = worker->errors.size();
    ubii::Session again;
    again.set_id(session.id());
    start(nodes, again);
    poll_all(
        nodes, [] { return false; }, 1s);
    EXPECT_EQ(worker->node->session_modules().size(), 1u);
    EXPECT_EQ(broken_created.load(), 1) << "a failed module is tried once per start record only";

    auto unknown = client->sessions().stop("no-such-session");
    ASSERT_TRUE(poll_all(
        nodes, [&] { return unknown.done(); }, 5s));
    EXPECT_FALSE(unknown.result().ok());
    EXPECT_EQ(worker->node->session_modules().size(), 1u);
    client->sessions().stop(session.id());
    poll_all(
        nodes, [&] { return worker->node->session_modules().empty(); }, 10s);
    EXPECT_TRUE(worker->node->session_modules().empty());
    EXPECT_GE(worker->errors.size(), errors_before);
}

// The master dies mid-session and a new one starts on the same ports: the session died with it,
// the node reconnects (to a master with another id) and stops the session's module on its own.
TEST(SessionMasterRestart, ModulesOfADeadMastersSessionsAreStopped)
{
    const int port_base = 8501;
    const auto master = [port_base](const std::string &action) {
        const std::string command =
            std::string("UBII_MASTER_SOURCE='") + UBII_CURRENT_MASTER_SOURCE + "' " +
            UBII_MASTER_SCRIPT + " " + action + " " + UBII_RESTART_MASTER_STATE +
            (action == "start" ? " " + std::to_string(port_base) : "") + " >/dev/null";
        return std::system(command.c_str()) == 0;
    };
    ASSERT_TRUE(master("start")) << "could not start the test's own master";
    {
        ubii::NodeOptions options;
        options.service_url = "tcp://127.0.0.1:" + std::to_string(port_base);
        options.topic_url = "tcp://127.0.0.1:" + std::to_string(port_base + 2);
        options.service_timeout = 1000ms;
        options.reconnect.first_delay = 100ms;
        options.reconnect.max_delay = 500ms;
        options.is_dedicated_processing_node = true;
        options.name = "libubii-restart";
        ubii::Node worker(options);
        std::vector<SessionEvent> events;
        worker.on_session_event([&](const SessionEvent &event) { events.push_back(event); });
        ubii::ModuleRegistry modules;
        modules.add(make_doubler);
        worker.serve_sessions(std::move(modules));
        worker.connect(10s);
        options.name = "restart-client";
        options.is_dedicated_processing_node = false;
        ubii::Node client(options);
        client.connect(10s);

        SessionSpec spec("restart");
        auto &doubler = spec.module("libubii_doubler");
        map_input(doubler, "x", "/restart/in");
        map_output(doubler, "y", "/restart/out");
        auto started = client.sessions().start(spec.session);
        const auto poll_both = [&](const std::function<bool()> &done, std::chrono::seconds limit) {
            const auto until = std::chrono::steady_clock::now() + limit;
            while (!done() && std::chrono::steady_clock::now() < until) {
                worker.poll(5ms);
                client.poll(5ms);
            }
            return done();
        };
        ASSERT_TRUE(poll_both([&] { return worker.session_modules().size() == 1; }, 10s));

        ASSERT_TRUE(master("stop"));
        ASSERT_TRUE(master("start"));
        ASSERT_TRUE(poll_both([&] { return worker.session_modules().empty(); }, 20s))
            << "the module of the dead master's session still runs";
        EXPECT_EQ(events.back().kind, SessionEvent::Kind::stopped);
        EXPECT_NE(events.back().detail.find("master restarted"), std::string::npos);
        EXPECT_TRUE(worker.ready());
    }
    master("stop");
}

} // namespace
