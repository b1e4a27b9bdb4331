#ifndef UBII_RESULT_HPP
#define UBII_RESULT_HPP

// ubii::Result<T>: a value or the error that took its place, for the calls that must not throw
// where they report (service call callbacks, hot paths). value() rethrows the error.

#include <exception>
#include <optional>
#include <string>
#include <utility>

#include "ubii/error.hpp"

namespace ubii
{

template <class T> class Result
{
  public:
    static Result success(T value)
    {
        Result result;
        result.value_ = std::move(value);
        return result;
    }
    // `error` must hold an exception (an ubii::Error gives status()).
    static Result failure(std::exception_ptr error)
    {
        Result result;
        result.error_ = std::move(error);
        try {
            std::rethrow_exception(result.error_);
        } catch (const Error &e) {
            result.status_ = e.status();
            result.message_ = e.what();
        } catch (const std::exception &e) {
            result.status_ = Status::callback_threw;
            result.message_ = e.what();
        } catch (...) {
            result.status_ = Status::callback_threw;
            result.message_ = "unknown exception";
        }
        return result;
    }

    bool ok() const noexcept
    {
        return value_.has_value();
    }
    explicit operator bool() const noexcept
    {
        return ok();
    }
    Status status() const noexcept
    {
        return status_;
    }
    // "" when ok().
    const std::string &error_message() const noexcept
    {
        return message_;
    }
    std::exception_ptr error() const noexcept
    {
        return error_;
    }
    // The value; the error's exception if there is none.
    const T &value() const
    {
        if (!value_)
            std::rethrow_exception(error_);
        return *value_;
    }
    T &value()
    {
        if (!value_)
            std::rethrow_exception(error_);
        return *value_;
    }

  private:
    Result() = default;
    std::optional<T> value_;
    std::exception_ptr error_;
    Status status_ = Status::ok;
    std::string message_;
};

} // namespace ubii

#endif
