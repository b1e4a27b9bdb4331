#include <thread>

#include "ubii/testing.hpp"

namespace ubii::testing
{

namespace
{

// Polls until the master confirmed `node`'s subscriptions (the test fails if it does not in time).
void await_subscriptions(ubii::Node &node, const Probe::Poll &poll,
                         std::chrono::milliseconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (node.subscriptions_pending() && std::chrono::steady_clock::now() < deadline)
        poll(std::chrono::milliseconds(5));
    if (node.subscriptions_pending())
        ADD_FAILURE() << "the master did not confirm the subscriptions within " << timeout.count()
                      << " ms";
}

} // namespace

Probe::Probe(ubii::Node &node, const std::string &pattern, bool regex, Poll poll)
    : poll_(std::move(poll)), pattern_(pattern),
      received_(std::make_shared<std::deque<ubii::Record>>())
{
    auto keep = [received = received_](const ubii::Record &record) {
        received->push_back(record); // a copy: the lent record lives only during the callback
    };
    subscription_ = regex ? node.subscribe_regex(pattern, keep) : node.subscribe(pattern, keep);
    await_subscriptions(node, poll_, std::chrono::seconds(10));
}

ubii::Record Probe::next(std::chrono::milliseconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (received_->empty() && std::chrono::steady_clock::now() < deadline)
        poll_(std::chrono::milliseconds(5));
    if (received_->empty()) {
        ADD_FAILURE() << "no record on " << pattern_ << " within " << timeout.count() << " ms";
        return {};
    }
    ubii::Record record = std::move(received_->front());
    received_->pop_front();
    return record;
}

void MasterTest::SetUp()
{
    std::string why;
    endpoints_ = shared_master(&why);
    if (endpoints_ == nullptr)
        GTEST_SKIP() << "no Ubi-Interact master for this test: " << why;
    node_ = std::make_unique<ubii::Node>(
        node_options(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    node_->connect(default_timeout);
}

void MasterTest::TearDown()
{
    for (const std::string &id : sessions_) {
        const auto stopped = node_->sessions().stop(id);
        run_until([&stopped] { return stopped.done(); }, default_timeout);
    }
    sessions_.clear();
    other_nodes_.clear();
    node_.reset();
}

ubii::NodeOptions MasterTest::node_options(const std::string &name) const
{
    ubii::NodeOptions options;
    options.service_url = endpoints_->service_url;
    options.topic_url = endpoints_->topic_url;
    options.name = name;
    return options;
}

ubii::Node &MasterTest::add_node(const std::string &name)
{
    ubii::Node &added = other_nodes_.emplace_back(node_options(name));
    added.connect(default_timeout);
    return added;
}

void MasterTest::poll_all(std::chrono::milliseconds slice)
{
    node_->poll(other_nodes_.empty() ? slice : std::chrono::milliseconds(0));
    for (ubii::Node &other : other_nodes_)
        other.poll(std::chrono::milliseconds(0));
    if (!other_nodes_.empty())
        std::this_thread::sleep_for(std::min(slice, std::chrono::milliseconds(1)));
}

void MasterTest::run_for(std::chrono::milliseconds duration)
{
    const auto deadline = std::chrono::steady_clock::now() + duration;
    while (std::chrono::steady_clock::now() < deadline)
        poll_all(std::chrono::milliseconds(5));
}

bool MasterTest::run_until(const std::function<bool()> &done, std::chrono::milliseconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
        if (std::chrono::steady_clock::now() >= deadline)
            return false;
        poll_all(std::chrono::milliseconds(5));
    }
    return true;
}

std::string MasterTest::start_session(ubii::ModuleRegistry modules, const ubii::Session &session)
{
    struct Progress {
        int started = 0;
        std::string failure;
    };
    auto progress = std::make_shared<Progress>();
    ubii::NodeOptions options = node_options("session-node");
    options.is_dedicated_processing_node = true;
    ubii::Node &serving = other_nodes_.emplace_back(options);
    serving.on_session_event([progress](const ubii::SessionEvent &event) {
        if (event.kind == ubii::SessionEvent::Kind::confirmed_started)
            ++progress->started;
        else if (event.kind == ubii::SessionEvent::Kind::failed && progress->failure.empty())
            progress->failure = event.module_name + ": " + event.detail;
    });
    serving.serve_sessions(std::move(modules));
    serving.connect(default_timeout);
    const auto call = node_->sessions().start(session);
    if (!run_until([&call] { return call.done(); }, default_timeout)) {
        ADD_FAILURE() << "the master did not answer the session start";
        return "";
    }
    ubii::Session started;
    try {
        started = call.get();
    } catch (const ubii::Error &error) {
        ADD_FAILURE() << "the master refused the session: " << error.what();
        return "";
    }
    sessions_.push_back(started.id());
    const int expected = started.processing_modules_size();
    run_until([&] { return progress->started >= expected || !progress->failure.empty(); },
              default_timeout);
    if (!progress->failure.empty())
        ADD_FAILURE() << "a module of the session failed: " << progress->failure;
    else if (progress->started < expected)
        ADD_FAILURE() << progress->started << " of " << expected
                      << " modules of the session started within " << default_timeout.count()
                      << " ms";
    return progress->failure.empty() && progress->started >= expected ? started.id() : "";
}

Probe MasterTest::probe(const std::string &topic)
{
    return Probe(*node_, topic, false,
                 [this](std::chrono::milliseconds slice) { poll_all(slice); });
}

Probe MasterTest::probe_regex(const std::string &regex)
{
    return Probe(*node_, regex, true, [this](std::chrono::milliseconds slice) { poll_all(slice); });
}

ubii::RunningModule MasterTest::run_module(std::unique_ptr<ubii::ProcessingModule> module,
                                           const ubii::Wiring &wiring)
{
    ubii::Node &processing = add_node(module->name() + "-node");
    ubii::RunningModule running = processing.run(std::move(module), wiring);
    // Its input subscriptions reach the master before the test publishes.
    await_subscriptions(
        processing, [this](std::chrono::milliseconds slice) { poll_all(slice); }, default_timeout);
    return running;
}

} // namespace ubii::testing
