#include "fake_port.h"

#include <cstring>

#include "pb_test_callbacks.h"
#include "ubii/services/serviceReply.pb.h"
#include "ubii/topicData/topicData.pb.h"

namespace ubii_test
{

namespace
{
FakePort &self(void *context)
{
    return *static_cast<FakePort *>(context);
}

template <typename Message>
std::vector<uint8_t> encode(const pb_msgdesc_t *fields, const Message &message)
{
    std::vector<uint8_t> out(4096);
    pb_ostream_t stream = pb_ostream_from_buffer(out.data(), out.size());
    if (!pb_encode(&stream, fields, &message)) {
        return {};
    }
    out.resize(stream.bytes_written);
    return out;
}

// Subscription lists are callbacks; bound while the request is decoded.
struct SubscriptionLists {
    StringValues subscribe_topics, unsubscribe_topics, subscribe_regexes, unsubscribe_regexes;
};

bool bind_lists(pb_istream_t *, const pb_field_t *field, void **arg)
{
    if (field->tag == ubii_services_ServiceRequest_topic_subscription_tag) {
        auto *lists = static_cast<SubscriptionLists *>(*arg);
        auto *s = static_cast<ubii_services_request_TopicSubscription *>(field->pData);
        decode_into(s->subscribe_topics, lists->subscribe_topics);
        decode_into(s->unsubscribe_topics, lists->unsubscribe_topics);
        decode_into(s->subscribe_topic_regexp, lists->subscribe_regexes);
        decode_into(s->unsubscribe_topic_regexp, lists->unsubscribe_regexes);
    }
    return true;
}
} // namespace

FakePort::FakePort()
{
    answer = [](const ubii_services_ServiceRequest &) { return std::nullopt; };
}

ubii_port FakePort::port()
{
    static const ubii_port_vtable vtable = {open,    close, get_state, send_begin, send_commit,
                                            receive, wait,  pollfds,   monotonic,  epoch_ms};
    return ubii_port{&vtable, this};
}

void FakePort::push_topic(const std::vector<uint8_t> &bytes, unsigned flags)
{
    channels_[UBII_CHANNEL_TOPIC].inbox.push_back({bytes, flags});
}

void FakePort::set_state(ubii_channel channel, ubii_channel_state state)
{
    channels_[channel].state = state;
}

void FakePort::on_service_request(const std::vector<uint8_t> &bytes)
{
    SubscriptionLists lists;
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    request.cb_type.funcs.decode = bind_lists;
    request.cb_type.arg = &lists;
    pb_istream_t stream = pb_istream_from_buffer(bytes.data(), bytes.size());
    if (!pb_decode(&stream, ubii_services_ServiceRequest_fields, &request)) {
        return;
    }
    requests.push_back(request);
    request_bytes.push_back(bytes);
    auto append = [](std::vector<std::string> &to, const StringValues &from) {
        to.insert(to.end(), from.values.begin(), from.values.end());
    };
    append(subscribe_topics, lists.subscribe_topics);
    append(unsubscribe_topics, lists.unsubscribe_topics);
    append(subscribe_regexes, lists.subscribe_regexes);
    append(unsubscribe_regexes, lists.unsubscribe_regexes);
    if (auto reply = answer(request)) {
        channels_[UBII_CHANNEL_SERVICE].inbox.push_back({*reply, 0});
    }
}

ubii_status FakePort::open(void *context, ubii_channel which, const char *, const char *client_id)
{
    FakePort &port = self(context);
    port.opens[which]++;
    Channel &ch = port.channels_[which];
    ch.inbox.clear();
    ch.state = which == UBII_CHANNEL_SERVICE || port.topic_opens ? UBII_CHANNEL_OPEN
                                                                 : UBII_CHANNEL_CONNECTING;
    if (which == UBII_CHANNEL_TOPIC) {
        port.topic_client_id = client_id != nullptr ? client_id : "";
    }
    return UBII_OK;
}

void FakePort::close(void *context, ubii_channel which)
{
    Channel &ch = self(context).channels_[which];
    ch.state = UBII_CHANNEL_CLOSED;
    ch.inbox.clear();
}

ubii_channel_state FakePort::get_state(void *context, ubii_channel which)
{
    return self(context).channels_[which].state;
}

ubii_status FakePort::send_begin(void *context, ubii_channel which, size_t size, uint8_t **buffer)
{
    Channel &ch = self(context).channels_[which];
    if (ch.state != UBII_CHANNEL_OPEN) {
        return UBII_ERR_NOT_CONNECTED;
    }
    ch.outgoing.assign(size, 0);
    *buffer = ch.outgoing.data();
    return UBII_OK;
}

ubii_status FakePort::send_commit(void *context, ubii_channel which, unsigned flags)
{
    FakePort &port = self(context);
    if (which == UBII_CHANNEL_SERVICE) {
        port.on_service_request(port.channels_[which].outgoing);
    } else {
        port.topic_sent.push_back({port.channels_[which].outgoing, flags});
    }
    return UBII_OK;
}

ubii_status FakePort::receive(void *context, ubii_channel which, const uint8_t **data, size_t *size,
                              unsigned *flags)
{
    Channel &ch = self(context).channels_[which];
    if (ch.inbox.empty() || ch.state != UBII_CHANNEL_OPEN) {
        return UBII_ERR_WOULD_BLOCK;
    }
    ch.current = ch.inbox.front();
    ch.inbox.pop_front();
    *data = ch.current.bytes.data();
    *size = ch.current.bytes.size();
    *flags = ch.current.flags;
    return UBII_OK;
}

ubii_status FakePort::wait(void *context, int timeout_ms)
{
    FakePort &port = self(context);
    bool pending = !port.channels_[0].inbox.empty() || !port.channels_[1].inbox.empty();
    if (!pending && timeout_ms > 0) {
        port.now += static_cast<uint64_t>(timeout_ms);
    }
    return UBII_OK;
}

int FakePort::pollfds(void *, ubii_pollfd *, int)
{
    return 0;
}

uint64_t FakePort::monotonic(void *context)
{
    return self(context).now;
}

int64_t FakePort::epoch_ms(void *context)
{
    return self(context).epoch;
}

std::vector<uint8_t> server_reply(const std::string &topic_port)
{
    ubii_services_ServiceReply reply = ubii_services_ServiceReply_init_zero;
    reply.which_type = ubii_services_ServiceReply_server_tag;
    std::strcpy(reply.type.server.name, "fake-master");
    std::strcpy(reply.type.server.port_topic_data_zmq, topic_port.c_str());
    return encode(ubii_services_ServiceReply_fields, reply);
}

std::vector<uint8_t> client_reply(const std::string &id)
{
    ubii_services_ServiceReply reply = ubii_services_ServiceReply_init_zero;
    reply.which_type = ubii_services_ServiceReply_client_tag;
    std::strcpy(reply.type.client.id, id.c_str());
    return encode(ubii_services_ServiceReply_fields, reply);
}

std::vector<uint8_t> success_reply()
{
    ubii_services_ServiceReply reply = ubii_services_ServiceReply_init_zero;
    reply.which_type = ubii_services_ServiceReply_success_tag;
    std::strcpy(reply.type.success.title, "Success");
    return encode(ubii_services_ServiceReply_fields, reply);
}

std::vector<uint8_t> error_reply(const std::string &title, const std::string &message)
{
    ubii_services_ServiceReply reply = ubii_services_ServiceReply_init_zero;
    reply.which_type = ubii_services_ServiceReply_error_tag;
    std::strcpy(reply.type.error.title, title.c_str());
    std::strcpy(reply.type.error.message, message.c_str());
    return encode(ubii_services_ServiceReply_fields, reply);
}

std::vector<uint8_t> double_record(const std::string &topic, double value)
{
    ubii_topicData_TopicData data = ubii_topicData_TopicData_init_zero;
    data.which_type = ubii_topicData_TopicData_topic_data_record_tag;
    std::strcpy(data.type.topic_data_record.topic, topic.c_str());
    data.type.topic_data_record.which_type = ubii_topicData_TopicDataRecord_double__tag;
    data.type.topic_data_record.type.double_ = value;
    return encode(ubii_topicData_TopicData_fields, data);
}

std::vector<uint8_t> topic_data_error(const std::string &title)
{
    ubii_topicData_TopicData data = ubii_topicData_TopicData_init_zero;
    data.which_type = ubii_topicData_TopicData_error_tag;
    std::strcpy(data.type.error.title, title.c_str());
    return encode(ubii_topicData_TopicData_fields, data);
}

} // namespace ubii_test
