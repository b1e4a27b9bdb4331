#include "test_node.h"

#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <unistd.h>

namespace ubii_test
{

int port_base()
{
    const char *text = std::getenv("UBII_TEST_PORT_BASE");
    return text != nullptr ? std::atoi(text) : 8101;
}

std::string service_url()
{
    return "tcp://127.0.0.1:" + std::to_string(port_base());
}

std::string topic_zmq_url()
{
    return "tcp://127.0.0.1:" + std::to_string(port_base() + 2);
}

std::string topic_ws_url()
{
    return "ws://127.0.0.1:" + std::to_string(port_base() + 3);
}

std::string unique_topic(const std::string &stem)
{
    static std::atomic<int> counter{0};
    return "/libubii-test/" + std::to_string(getpid()) + "/" + std::to_string(counter++) + stem;
}

TestNode::TestNode(const std::string &name, const std::string &topic_url,
                   const std::string &service, Tls tls)
    : name_(name), topic_url_(topic_url), service_url_(service), port_(tls),
      node_(std::make_unique<ubii_node>())
{
    ubii_config_init(&config_);
    config_.service_url = service_url_.c_str();
    config_.topic_url = topic_url_.empty() ? nullptr : topic_url_.c_str();
    config_.client_name = name_.c_str();
    config_.service_timeout_ms = 3000;
    config_.on_error = on_error;
    config_.on_error_user = this;
    config_.on_state = on_state;
    config_.on_state_user = this;
}

TestNode::~TestNode()
{
    if (initialised_) {
        ubii_node_stop_wait(node_.get(), 3000);
    }
}

bool TestNode::poll_until(const std::function<bool()> &done, std::chrono::milliseconds timeout)
{
    if (!initialised_) {
        if (ubii_node_init(node_.get(), sizeof(ubii_node), &config_, port_.get()) != UBII_OK) {
            return false;
        }
        initialised_ = true;
    }
    auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
        if (std::chrono::steady_clock::now() >= deadline) {
            return false;
        }
        ubii_node_poll(node_.get(), 10);
    }
    return true;
}

bool TestNode::wait_ready(std::chrono::milliseconds timeout)
{
    if (!initialised_) {
        poll_until([] { return true; });
    }
    if (ubii_node_state(node_.get()) == UBII_STATE_STOPPED && start() != UBII_OK) {
        return false;
    }
    return poll_until([this] { return ubii_node_state(node_.get()) == UBII_STATE_READY; }, timeout);
}

bool TestNode::start_and_wait_failed(uint32_t attempts, std::chrono::milliseconds timeout)
{
    config_.max_reconnect_attempts = attempts;
    config_.reconnect_min_ms = 50;
    if (!poll_until([] { return true; }) || start() != UBII_OK) {
        return false;
    }
    return poll_until([this] { return ubii_node_state(node_.get()) == UBII_STATE_FAILED; },
                      timeout);
}

ubii_subscription TestNode::collect(const std::string &pattern, bool regex)
{
    ubii_subscription handle = 0;
    ubii_status status =
        regex ? ubii_subscribe_regex(node_.get(), pattern.c_str(), on_record, this, &handle)
              : ubii_subscribe(node_.get(), pattern.c_str(), on_record, this, &handle);
    if (status != UBII_OK) {
        throw std::runtime_error(std::string("subscribe failed: ") + ubii_strerror(status));
    }
    return handle;
}

void TestNode::on_record(ubii_node *, const ubii_record *record, void *user)
{
    auto *self = static_cast<TestNode *>(user);
    Received r;
    r.topic = record->topic;
    r.type = record->type;
    r.value.assign(record->value, record->value + record->value_size);
    r.scalar = record->scalar;
    r.has_timestamp = record->has_timestamp;
    r.millis = record->timestamp_millis;
    self->received_.push_back(std::move(r));
}

void TestNode::on_error(ubii_node *, ubii_status status, const char *detail, void *user)
{
    static_cast<TestNode *>(user)->errors_.emplace_back(status, detail);
}

void TestNode::on_state(ubii_node *node, ubii_state, ubii_state current, ubii_status, void *user)
{
    auto *self = static_cast<TestNode *>(user);
    self->states_.push_back(current);
    if (current == UBII_STATE_OPENING) {
        self->registered_ids_.emplace_back(ubii_node_client_id(node));
    }
}

} // namespace ubii_test
