#include "ubii/error.hpp"

namespace ubii
{

const char *describe(Status status) noexcept
{
    if (status == Status::callback_threw)
        return "an application callback threw an exception";
    return ubii_strerror(static_cast<ubii_status>(status));
}

ServiceError::ServiceError(std::string service, std::string title, std::string message)
    : Error(Status::broker, service + ": the master replied with an error: " + title +
                                (message.empty() ? "" : ": " + message)),
      service_(std::move(service)), title_(std::move(title)), message_(std::move(message))
{
}

void throw_status(Status status, const std::string &context)
{
    const std::string what = context + ": " + describe(status);
    switch (status) {
    case Status::invalid_argument:
    case Status::buffer_too_small:
        throw InvalidArgument(what);
    case Status::encode:
        throw EncodeError(what);
    case Status::decode:
        throw DecodeError(what);
    case Status::unexpected_reply:
        throw UnexpectedReply(what);
    case Status::timeout:
        throw Timeout(what);
    case Status::not_connected:
        throw NotConnected(what);
    case Status::full:
        throw Full(what);
    case Status::would_block:
        throw WouldBlock(what);
    case Status::transport:
        throw TransportError(what);
    case Status::unsupported:
        throw Unsupported(what);
    case Status::too_large:
        throw TooLarge(what);
    case Status::wrong_type:
        throw WrongType(what);
    case Status::not_found:
        throw NotFound(what);
    case Status::state:
        throw StateError(what);
    case Status::cancelled:
        throw Cancelled(what);
    case Status::ok:
    case Status::broker:
    case Status::callback_threw:
        break;
    }
    throw Error(status, what);
}

} // namespace ubii
