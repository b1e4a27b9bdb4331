#ifndef UBII_SERVICE_CALL_HPP
#define UBII_SERVICE_CALL_HPP

// ubii::Call<T>: a service call on its way. The node resolves it inside poll() with the reply's
// member as a T, or with the error that came instead (ubii::ServiceError for the master's error
// reply, ubii::Timeout, ubii::Cancelled when the node stopped or reconnected, ...).
//
//     auto call = node.master().server_configuration();
//     call.then([](const ubii::Result<ubii::Server> &server) { ... });   // inside a later poll()
//     ubii::Server server = node.wait(call, 2s);                         // or poll until it is
//     done
//
// A Call is a cheap handle (copies share the call); dropping every handle does not cancel it.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ubii/error.hpp"
#include "ubii/messages.hpp"
#include "ubii/result.hpp"

namespace ubii
{

namespace detail
{
template <class T> struct CallState {
    std::string service;
    std::optional<Result<T>> result;
    std::vector<std::function<void(const Result<T> &)>> continuations;

    void resolve(Result<T> outcome)
    {
        result = std::move(outcome);
        auto pending = std::move(continuations);
        continuations.clear();
        for (auto &continuation : pending)
            continuation(*result);
    }
};

// The reply's member if it is a `type`: ServiceError for an error reply, UnexpectedReply for
// another member (or none).
const google::protobuf::Message &reply_payload(const ServiceReply &reply,
                                               const std::string &service,
                                               const google::protobuf::Descriptor *type);
// The whole reply, unless it is an error reply (ServiceError).
void check_reply(const ServiceReply &reply, const std::string &service);

template <class T> T reply_member(const ServiceReply &reply, const std::string &service)
{
    if constexpr (std::is_same_v<T, ServiceReply>) {
        check_reply(reply, service);
        return reply;
    } else {
        return static_cast<const T &>(reply_payload(reply, service, T::descriptor()));
    }
}
} // namespace detail

template <class T> class Call
{
  public:
    Call() = default;
    explicit Call(std::shared_ptr<detail::CallState<T>> state) : state_(std::move(state))
    {
    }

    bool valid() const noexcept
    {
        return state_ != nullptr;
    }
    // The service topic called.
    const std::string &service() const
    {
        return state().service;
    }
    bool done() const
    {
        return state().result.has_value();
    }
    // ubii::StateError while the call is not done.
    const Result<T> &result() const
    {
        if (!done())
            throw StateError("the call to " + service() + " has no reply yet");
        return *state().result;
    }
    // The reply; the call's error as an exception.
    const T &get() const
    {
        return result().value();
    }
    // Runs `continuation` with the outcome inside the poll() that resolves the call, or at once if
    // it is done. An exception it throws is reported through the node's error event.
    Call &then(std::function<void(const Result<T> &)> continuation)
    {
        if (done())
            continuation(*state().result);
        else
            state().continuations.push_back(std::move(continuation));
        return *this;
    }

  private:
    detail::CallState<T> &state() const
    {
        if (!state_)
            throw StateError("an empty ubii::Call");
        return *state_;
    }
    std::shared_ptr<detail::CallState<T>> state_;
};

} // namespace ubii

#endif
