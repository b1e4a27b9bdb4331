// A C++ application built against an installed libubii's C++ layer: values and records work, the
// installed protobuf classes round-trip a record through its wire bytes, and a node given a master
// that is not there says so with ubii::Timeout within the time it was given (no master needed).
#include <chrono>
#include <cstdio>
#include <string>

#include "ubii/ubii.hpp"

namespace
{

bool fail(const char *why)
{
    std::fprintf(stderr, "consumer_cpp: %s\n", why);
    return false;
}

bool values_and_records_work()
{
    const ubii::Value hand = ubii::vector3(1, 2, 3);
    if (hand.type() != ubii::RecordType::VECTOR3 || !hand.holds<ubii::Vector3>())
        return fail("a Vector3 value is not a VECTOR3");
    try {
        (void)hand.as<double>();
        return fail("a Vector3 value was read as a double");
    } catch (const ubii::WrongType &) {
    }

    ubii::Record record("/consumer/hand", hand);
    const ubii::Record kept = record;
    const ubii::Record moved = std::move(record);
    if (kept.topic() != "/consumer/hand" || kept.as<ubii::Vector3>().y() != 2.0 ||
        moved.as<ubii::Vector3>().z() != 3.0)
        return fail("the record did not keep its topic and value");

    // Through the wire format with the installed generated classes (ubii/messages/...).
    ubii::TopicDataRecord message;
    message.set_topic(std::string(kept.topic()));
    *message.mutable_vector3() = kept.as<ubii::Vector3>();
    ubii::TopicDataRecord parsed;
    if (!parsed.ParseFromString(message.SerializeAsString()) || parsed.topic() != kept.topic() ||
        parsed.vector3().x() != 1.0)
        return fail("the TopicDataRecord did not round-trip through its bytes");
    return true;
}

bool connect_times_out()
{
    ubii::NodeOptions options;
    options.service_url = "tcp://127.0.0.1:9"; // nothing listens there
    options.name = "libubii-consumer-cpp";
    ubii::Node node(options);
    const auto start = std::chrono::steady_clock::now();
    try {
        node.connect(std::chrono::milliseconds(300));
        return fail("connected to nothing");
    } catch (const ubii::Timeout &) {
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(3))
        return fail("connect() overran its timeout");
    return true;
}

} // namespace

int main()
{
    if (!values_and_records_work() || !connect_times_out())
        return 1;
    std::printf("consumer_cpp: %s member %s round-tripped, connect timed out as asked\n",
                std::string(ubii::message_format(ubii::RecordType::VECTOR3)).c_str(),
                std::string(ubii::record_type_name(ubii::RecordType::VECTOR3)).c_str());
    return 0;
}
