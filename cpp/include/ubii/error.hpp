#ifndef UBII_ERROR_HPP
#define UBII_ERROR_HPP

// The C++ layer's errors: one exception type per ubii_status, all derived from ubii::Error, and
// ubii::Status for the calls that report instead of throwing (try_publish, Result).
//
// Exceptions never cross into the C core: every callback the core calls catches what the
// application's code throws and reports it through the node's error event (Node::on_error).

#include <stdexcept>
#include <string>

#include "ubii/status.h"

namespace ubii
{

// ubii_status as a scoped enum; the values are the C ones.
enum class Status : int {
    ok = UBII_OK,
    invalid_argument = UBII_ERR_INVALID_ARGUMENT,
    buffer_too_small = UBII_ERR_BUFFER_TOO_SMALL,
    encode = UBII_ERR_ENCODE,
    decode = UBII_ERR_DECODE,
    unexpected_reply = UBII_ERR_UNEXPECTED_REPLY,
    broker = UBII_ERR_BROKER,
    timeout = UBII_ERR_TIMEOUT,
    not_connected = UBII_ERR_NOT_CONNECTED,
    full = UBII_ERR_FULL,
    would_block = UBII_ERR_WOULD_BLOCK,
    transport = UBII_ERR_TRANSPORT,
    unsupported = UBII_ERR_UNSUPPORTED,
    too_large = UBII_ERR_TOO_LARGE,
    wrong_type = UBII_ERR_WRONG_TYPE,
    not_found = UBII_ERR_NOT_FOUND,
    state = UBII_ERR_STATE,
    cancelled = UBII_ERR_CANCELLED,
    // Not from the core: an exception thrown by the application's own callback.
    callback_threw = -100
};

inline Status to_status(ubii_status status)
{
    return static_cast<Status>(status);
}
// A static English description, as ubii_strerror.
const char *describe(Status status) noexcept;

class Error : public std::runtime_error
{
  public:
    Error(Status status, const std::string &what) : std::runtime_error(what), status_(status)
    {
    }
    Status status() const noexcept
    {
        return status_;
    }

  private:
    Status status_;
};

#define UBII_ERROR_CLASS(name, status_value)                                                       \
    class name : public Error                                                                      \
    {                                                                                              \
      public:                                                                                      \
        explicit name(const std::string &what) : Error(status_value, what)                         \
        {                                                                                          \
        }                                                                                          \
    };
UBII_ERROR_CLASS(InvalidArgument, Status::invalid_argument)
UBII_ERROR_CLASS(EncodeError, Status::encode)
UBII_ERROR_CLASS(DecodeError, Status::decode)
UBII_ERROR_CLASS(UnexpectedReply, Status::unexpected_reply)
UBII_ERROR_CLASS(Timeout, Status::timeout)
UBII_ERROR_CLASS(NotConnected, Status::not_connected)
UBII_ERROR_CLASS(Full, Status::full)
UBII_ERROR_CLASS(WouldBlock, Status::would_block)
UBII_ERROR_CLASS(TransportError, Status::transport)
UBII_ERROR_CLASS(Unsupported, Status::unsupported)
UBII_ERROR_CLASS(TooLarge, Status::too_large)
UBII_ERROR_CLASS(WrongType, Status::wrong_type)
UBII_ERROR_CLASS(NotFound, Status::not_found)
UBII_ERROR_CLASS(StateError, Status::state)
UBII_ERROR_CLASS(Cancelled, Status::cancelled)
#undef UBII_ERROR_CLASS

// The master answered a service call with ubii.general.Error.
class ServiceError : public Error
{
  public:
    ServiceError(std::string service, std::string title, std::string message);
    const std::string &service() const noexcept
    {
        return service_;
    }
    const std::string &title() const noexcept
    {
        return title_;
    }
    const std::string &message() const noexcept
    {
        return message_;
    }

  private:
    std::string service_, title_, message_;
};

// Throws the exception of `status` (never for Status::ok), its text "<context>: <description>".
[[noreturn]] void throw_status(Status status, const std::string &context);

inline void check(ubii_status status, const char *context)
{
    if (status != UBII_OK)
        throw_status(to_status(status), context);
}
inline void check(ubii_status status, const std::string &context)
{
    if (status != UBII_OK)
        throw_status(to_status(status), context);
}

} // namespace ubii

#endif
