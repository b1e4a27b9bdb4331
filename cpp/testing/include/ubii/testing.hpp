#ifndef UBII_TESTING_HPP
#define UBII_TESTING_HPP

// ubii::testing: GoogleTest support for testing one's own nodes and processing modules against a
// real Ubi-Interact master (find_package(ubii COMPONENTS testing), target ubii::ubii_testing).
//
//     class ScaleTest : public ubii::testing::MasterTest {};
//
//     TEST_F(ScaleTest, DoublesWhatItGets)
//     {
//         auto module = run_module(std::make_unique<Scale>(),
//                                  ubii::Wiring().input("value", "/in").output("scaled", "/out"));
//         auto out = probe("/out");
//         node().publish("/in", 21.0);
//         EXPECT_EQ(out.next<double>(5s), 42.0);
//     }
//
// The first MasterTest of a test program starts the master the project's scripts install (the npm
// master, @tum-far/ubii-nodejs-backend 0.4.0, installed into UBII_CACHE_DIR or ~/.cache/libubii
// when missing); it runs until the program ends. Where the machine allows it, the test program
// first moves into a private network namespace with only a loopback interface (the master binds
// every interface; nothing outside sees it, and the program sees nothing outside), and the master
// takes its usual ports 8101-8104; elsewhere, or with UBII_TESTING_PRIVATE_NET=0, it runs on
// loopback with four free ports. When the master cannot be installed or started, every MasterTest
// is skipped with the reason.
//
// UBII_MASTER_SOURCE=DIR starts the current master from a checkout that scripts/current-master.sh
// prepared instead (the only master that assigns session modules to nodes).

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ubii/ubii.hpp"

namespace ubii::testing
{

// The master the test program runs against.
struct MasterEndpoints {
    std::string service_url; // tcp://127.0.0.1:BASE
    std::string topic_url;   // tcp://127.0.0.1:BASE+2
    std::string websocket_url;
    int port_base = 0;
    bool private_network = false;
    // Started from a checkout (UBII_MASTER_SOURCE): it assigns session modules to nodes.
    bool assigns_sessions = false;
};

// Starts the master once per program (thread-safe); nullptr, with `why` set, when it cannot.
const MasterEndpoints *shared_master(std::string *why);

// Records of one topic (or regex) that a test awaits. Receives from the moment probe() returns:
// the master has the subscription by then.
class Probe
{
  public:
    // `poll` polls the nodes of the test for at most the time it is given.
    using Poll = std::function<void(std::chrono::milliseconds)>;
    Probe(ubii::Node &node, const std::string &pattern, bool regex, Poll poll);
    // The next record, polling the node for at most `timeout`; the test fails (and the
    // Probe returns an empty record) when none comes.
    ubii::Record next(std::chrono::milliseconds timeout);
    // Its value as a T (a record of another type fails the test).
    template <class T> T next(std::chrono::milliseconds timeout)
    {
        const ubii::Record record = next(timeout);
        const T *value = record.value().get_if<T>();
        if (value == nullptr) {
            ADD_FAILURE() << "a record of " << ubii::record_type_name(record.type()) << " on "
                          << record.topic() << ", not the type asked for";
            return T{};
        }
        return *value;
    }
    // Records received and not taken by next() yet.
    std::size_t pending() const
    {
        return received_->size();
    }

  private:
    Poll poll_;
    std::string pattern_;
    std::shared_ptr<std::deque<ubii::Record>> received_;
    ubii::Subscription subscription_;
};

// A fixture with a node connected to the shared master.
class MasterTest : public ::testing::Test
{
  protected:
    void SetUp() override;
    void TearDown() override;

    const MasterEndpoints &master() const
    {
        return *endpoints_;
    }
    // The test's own node, connected.
    ubii::Node &node()
    {
        return *node_;
    }
    // Options for another node of this master.
    ubii::NodeOptions node_options(const std::string &name) const;
    // Another connected node (a second client), owned by the test.
    ubii::Node &add_node(const std::string &name);

    // Subscribes `pattern` on the test's node and returns once the master has the subscription.
    Probe probe(const std::string &topic);
    Probe probe_regex(const std::string &regex);

    // Runs `module` on a processing node of its own, wired to the master's topics as a session
    // would wire it, until the test ends: the test publishes to its inputs and probes its outputs
    // through the real master.
    ubii::RunningModule run_module(std::unique_ptr<ubii::ProcessingModule> module,
                                   const ubii::Wiring &wiring);

    // Starts `session` on the master with `modules` offered by a dedicated processing node of the
    // test that serves sessions, and returns the session's id once every module the session
    // names reports started (a refused or failed start fails the test and returns ""). Stopped
    // when the test ends. Only a master that assigns modules to nodes runs it: the current master
    // (UBII_MASTER_SOURCE); check master().assigns_sessions and skip without one.
    std::string start_session(ubii::ModuleRegistry modules, const ubii::Session &session);

    // Polls every node of the test for `duration`.
    void run_for(std::chrono::milliseconds duration);
    // Polls every node of the test until `done` holds (true) or `timeout` passes (false).
    bool run_until(const std::function<bool()> &done, std::chrono::milliseconds timeout);
    // Polls every node of the test once, waiting at most `slice` on the test's own.
    void poll_all(std::chrono::milliseconds slice);

    // How long connecting and the round trips of probe() and run_module() may take.
    std::chrono::milliseconds default_timeout = std::chrono::seconds(10);

  private:
    const MasterEndpoints *endpoints_ = nullptr;
    std::unique_ptr<ubii::Node> node_;
    std::deque<ubii::Node> other_nodes_;
    std::vector<std::string> sessions_;
};

} // namespace ubii::testing

#endif
