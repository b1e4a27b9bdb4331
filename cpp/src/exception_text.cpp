#include "exception_text.hpp"

namespace ubii::detail
{

std::string what_of(const std::exception_ptr &error)
{
    try {
        std::rethrow_exception(error);
    } catch (const std::exception &exception) {
        return exception.what();
    } catch (...) {
        return "an exception not derived from std::exception";
    }
}

} // namespace ubii::detail
