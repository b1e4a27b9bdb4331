#include "ubii/service_call.hpp"

namespace ubii::detail
{

namespace
{
const google::protobuf::FieldDescriptor *member_of(const ServiceReply &reply)
{
    const auto *oneof = ServiceReply::descriptor()->FindOneofByName("type");
    return reply.GetReflection()->GetOneofFieldDescriptor(reply, oneof);
}
} // namespace

void check_reply(const ServiceReply &reply, const std::string &service)
{
    if (reply.has_error())
        throw ServiceError(service, reply.error().title(), reply.error().message());
}

const google::protobuf::Message &reply_payload(const ServiceReply &reply,
                                               const std::string &service,
                                               const google::protobuf::Descriptor *type)
{
    check_reply(reply, service);
    const google::protobuf::FieldDescriptor *member = member_of(reply);
    if (member == nullptr)
        throw UnexpectedReply(service + ": the reply carries nothing, not a " + type->full_name());
    if (member->message_type() != type)
        throw UnexpectedReply(service + ": the reply carries " + member->name() + " (" +
                              member->message_type()->full_name() + "), not a " +
                              type->full_name());
    return reply.GetReflection()->GetMessage(reply, member);
}

} // namespace ubii::detail
