#ifndef UBII_CPP_EXCEPTION_TEXT_HPP
#define UBII_CPP_EXCEPTION_TEXT_HPP

#include <exception>
#include <string>

namespace ubii::detail
{

// What an exception says, for the error reports that name a module's or a plugin's failure.
std::string what_of(const std::exception_ptr &error);

} // namespace ubii::detail

#endif
