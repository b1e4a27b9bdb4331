#include "cpp_test_support.hpp"

#include <cstdlib>
#include <cstring>

#include <google/protobuf/util/message_differencer.h>

#include "test_node.h"

namespace ubii_cpp_test
{

using google::protobuf::FieldDescriptor;

std::string name(Transport transport)
{
    return transport == Transport::zmq ? "zmq" : "websocket";
}

ubii::NodeOptions options_for(const std::string &name, Transport transport)
{
    ubii::NodeOptions options;
    options.name = name;
    options.service_url = ubii_test::service_url();
    options.topic_url =
        transport == Transport::zmq ? ubii_test::topic_zmq_url() : ubii_test::topic_ws_url();
    const char *engine = std::getenv("UBII_TEST_ZMQ_ENGINE");
    if (engine != nullptr && std::strcmp(engine, "libzmq") == 0)
        options.zmq_engine = ubii::ZmqEngine::libzmq;
    return options;
}

namespace
{

void set_one(google::protobuf::Message &message, const FieldDescriptor *field, int seed, int depth)
{
    const auto *reflection = message.GetReflection();
    const bool repeated = field->is_repeated();
    const double real = 1.5 + seed * 0.25;
    const std::int32_t integer = -(seed + 3);
    switch (field->cpp_type()) {
    case FieldDescriptor::CPPTYPE_DOUBLE:
        repeated ? reflection->AddDouble(&message, field, real)
                 : reflection->SetDouble(&message, field, real);
        break;
    case FieldDescriptor::CPPTYPE_FLOAT:
        repeated ? reflection->AddFloat(&message, field, static_cast<float>(real))
                 : reflection->SetFloat(&message, field, static_cast<float>(real));
        break;
    case FieldDescriptor::CPPTYPE_INT32:
        repeated ? reflection->AddInt32(&message, field, integer)
                 : reflection->SetInt32(&message, field, integer);
        break;
    case FieldDescriptor::CPPTYPE_INT64:
        repeated ? reflection->AddInt64(&message, field, integer * 1000)
                 : reflection->SetInt64(&message, field, integer * 1000);
        break;
    case FieldDescriptor::CPPTYPE_UINT32:
        repeated ? reflection->AddUInt32(&message, field, static_cast<std::uint32_t>(seed + 2))
                 : reflection->SetUInt32(&message, field, static_cast<std::uint32_t>(seed + 2));
        break;
    case FieldDescriptor::CPPTYPE_UINT64:
        repeated ? reflection->AddUInt64(&message, field, static_cast<std::uint64_t>(seed + 2))
                 : reflection->SetUInt64(&message, field, static_cast<std::uint64_t>(seed + 2));
        break;
    case FieldDescriptor::CPPTYPE_BOOL:
        repeated ? reflection->AddBool(&message, field, true)
                 : reflection->SetBool(&message, field, true);
        break;
    case FieldDescriptor::CPPTYPE_STRING: {
        const std::string text = field->type() == FieldDescriptor::TYPE_BYTES
                                     ? std::string("\x00\xff\x01", 3) + char(seed)
                                     : field->name() + "-" + std::to_string(seed) + "-ü";
        repeated ? reflection->AddString(&message, field, text)
                 : reflection->SetString(&message, field, text);
        break;
    }
    case FieldDescriptor::CPPTYPE_ENUM: {
        const auto *values = field->enum_type();
        const auto *last = values->value(values->value_count() - 1);
        repeated ? reflection->AddEnum(&message, field, last)
                 : reflection->SetEnum(&message, field, last);
        break;
    }
    case FieldDescriptor::CPPTYPE_MESSAGE: {
        auto *child = repeated ? reflection->AddMessage(&message, field)
                               : reflection->MutableMessage(&message, field);
        fill(*child, seed + 1, depth - 1);
        break;
    }
    }
}

} // namespace

void fill(google::protobuf::Message &message, int seed, int depth)
{
    const auto *descriptor = message.GetDescriptor();
    for (int i = 0; i < descriptor->field_count(); ++i) {
        const FieldDescriptor *field = descriptor->field(i);
        if (field->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE && depth <= 0)
            continue;
        // One member per oneof: setting another would clear the first.
        if (const auto *oneof = field->real_containing_oneof();
            oneof != nullptr && oneof->field(0) != field)
            continue;
        set_one(message, field, seed + i, depth);
    }
}

namespace
{
template <class T> T member_value(int seed)
{
    T value{};
    if constexpr (std::is_same_v<T, ubii::Image2D>) {
        // An image must be consistent: libubii checks width x height x channels against the data.
        value.set_width(2);
        value.set_height(1);
        value.set_data_format(ubii::Image2D::RGB8);
        value.set_data(std::string("\xff\x00\x01\x02\xfe", 5) + static_cast<char>(seed));
    } else if constexpr (std::is_base_of_v<google::protobuf::Message, T>)
        fill(value, seed);
    else if constexpr (std::is_same_v<T, std::string>)
        value = "text-" + std::to_string(seed) + "-Grüße 🐋";
    else if constexpr (std::is_same_v<T, bool>)
        value = true;
    else
        value = static_cast<T>(seed * 3 + 1) / static_cast<T>(2);
    return value;
}
} // namespace

ubii::Value value_for(ubii::RecordType type, int seed)
{
    switch (type) {
#define UBII_TEST_VALUE_CASE(upper, number, member, format, cpp_type)                              \
    case ubii::RecordType::upper:                                                                  \
        return ubii::Value(ubii::RecordType::upper, member_value<cpp_type>(seed));
        UBII_RECORD_MEMBER_LIST(UBII_TEST_VALUE_CASE)
#undef UBII_TEST_VALUE_CASE
    case ubii::RecordType::NONE:
        break;
    }
    return ubii::Value();
}

bool same_value(const ubii::Value &a, const ubii::Value &b, std::string *difference)
{
    if (a.type() != b.type()) {
        if (difference != nullptr)
            *difference = "member " + std::string(ubii::record_type_name(a.type())) + " vs " +
                          std::string(ubii::record_type_name(b.type()));
        return false;
    }
    return a.visit([&](const auto &left) {
        using T = std::decay_t<decltype(left)>;
        const T &right = *b.get_if<T>();
        if constexpr (std::is_base_of_v<google::protobuf::Message, T>) {
            google::protobuf::util::MessageDifferencer differencer;
            std::string report;
            differencer.ReportDifferencesToString(&report);
            const bool equal = differencer.Compare(left, right);
            if (!equal && difference != nullptr)
                *difference = report;
            return equal;
        } else if constexpr (std::is_same_v<T, std::monostate>) {
            return true;
        } else {
            if (!(left == right) && difference != nullptr)
                *difference = "scalar values differ";
            return left == right;
        }
    });
}

namespace
{
ubii_port inner_of(void *port);
} // namespace

CountingPort::CountingPort() : inner_port_(inner_.get())
{
    // Every function forwards to the inner port with its own context; receive also counts.
    vtable_.open = [](void *p, ubii_channel c, const char *url, const char *id) {
        return inner_of(p).vtable->open(inner_of(p).context, c, url, id);
    };
    vtable_.close = [](void *p, ubii_channel c) {
        inner_of(p).vtable->close(inner_of(p).context, c);
    };
    vtable_.state = [](void *p, ubii_channel c) {
        return inner_of(p).vtable->state(inner_of(p).context, c);
    };
    vtable_.send_begin = [](void *p, ubii_channel c, std::size_t size, std::uint8_t **buffer) {
        return inner_of(p).vtable->send_begin(inner_of(p).context, c, size, buffer);
    };
    vtable_.send_commit = [](void *p, ubii_channel c, unsigned flags) {
        return inner_of(p).vtable->send_commit(inner_of(p).context, c, flags);
    };
    vtable_.receive = &CountingPort::receive;
    vtable_.wait = [](void *p, int timeout_ms) {
        return inner_of(p).vtable->wait(inner_of(p).context, timeout_ms);
    };
    vtable_.pollfds = [](void *p, ubii_pollfd *fds, int capacity) {
        return inner_of(p).vtable->pollfds(inner_of(p).context, fds, capacity);
    };
    vtable_.monotonic_ms = [](void *p) {
        return inner_of(p).vtable->monotonic_ms(inner_of(p).context);
    };
    vtable_.epoch_ms = [](void *p) { return inner_of(p).vtable->epoch_ms(inner_of(p).context); };
}

namespace
{
ubii_port inner_of(void *port)
{
    return static_cast<CountingPort *>(port)->inner();
}
} // namespace

ubii_port CountingPort::get()
{
    return ubii_port{&vtable_, this};
}

ubii_status CountingPort::receive(void *port, ubii_channel channel, const std::uint8_t **data,
                                  std::size_t *size, unsigned *flags)
{
    auto *self = static_cast<CountingPort *>(port);
    const ubii_status status =
        self->inner_port_.vtable->receive(self->inner_port_.context, channel, data, size, flags);
    if (status == UBII_OK && channel == UBII_CHANNEL_TOPIC &&
        !(*size == 4 && std::memcmp(*data, "PING", 4) == 0))
        ++self->topic_messages_;
    if (status == UBII_OK && channel == UBII_CHANNEL_SERVICE && self->replies_to_lose_ > 0) {
        --self->replies_to_lose_;
        return UBII_ERR_WOULD_BLOCK;
    }
    return status;
}

} // namespace ubii_cpp_test
