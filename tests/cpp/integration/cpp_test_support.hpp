#ifndef UBII_TEST_CPP_TEST_SUPPORT_HPP
#define UBII_TEST_CPP_TEST_SUPPORT_HPP

// Shared by the C++ layer's integration tests: node options for the test master, a value for
// every record member filled through reflection, and a port that counts what the master sends.

#include <cstdint>
#include <memory>
#include <string>

#include "test_port.h"
#include "ubii/ubii.hpp"

namespace ubii_cpp_test
{

enum class Transport { zmq, websocket };
std::string name(Transport transport);

// Options for the `master` fixture's ports; the tcp:// engine follows UBII_TEST_ZMQ_ENGINE.
ubii::NodeOptions options_for(const std::string &name, Transport transport = Transport::zmq);

// Sets every field of `message` (one oneof member each, one element of each repeated field) to a
// value derived from `seed`, none of them the default, recursing `depth` levels into messages.
void fill(google::protobuf::Message &message, int seed, int depth = 3);

// A value of member `type` with every field set (see fill).
ubii::Value value_for(ubii::RecordType type, int seed);

// Whether two values hold the same member with equal contents.
bool same_value(const ubii::Value &a, const ubii::Value &b, std::string *difference = nullptr);

// A Linux port that counts the records (not PINGs) the master sends on the topic channel, to see
// what the master forwards whether or not a subscription takes it; and that can lose service
// replies, to see a node time out against a master that did answer.
class CountingPort
{
  public:
    CountingPort();
    ubii_port get();
    std::uint64_t topic_messages() const
    {
        return topic_messages_;
    }
    ubii_port inner() const
    {
        return inner_port_;
    }
    // The next `count` service replies are dropped on arrival.
    void lose_service_replies(int count)
    {
        replies_to_lose_ = count;
    }

  private:
    static ubii_status receive(void *port, ubii_channel channel, const std::uint8_t **data,
                               std::size_t *size, unsigned *flags);
    ubii_test::TestPort inner_;
    ubii_port inner_port_{};
    ubii_port_vtable vtable_{};
    std::uint64_t topic_messages_ = 0;
    int replies_to_lose_ = 0;
};

} // namespace ubii_cpp_test

#endif
