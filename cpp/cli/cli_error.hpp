#ifndef UBII_CLI_ERROR_HPP
#define UBII_CLI_ERROR_HPP

// What `ubii-node` exits with: a script tells the kinds of failure apart by the code (README).

#include <stdexcept>
#include <string>

namespace ubii::cli
{

enum ExitCode : int {
    exit_ok = 0,
    // The master answered with an error (unknown service, a refused session, ...).
    exit_master_error = 1,
    // Wrong command line: unknown option, bad JSON, a value that is not of its type, no such file.
    exit_usage = 2,
    // No master at the URLs within --connect-timeout, or the connection broke.
    exit_no_master = 3,
    // No reply within --timeout; `sub` saw fewer than --count records within its --timeout.
    exit_timeout = 4,
    // `run`: no processing module to offer, or a module named that no plugin has.
    exit_modules = 5,
};

// A failure with its exit code; main() prints "ubii-node: <what>" and exits with it.
class CliError : public std::runtime_error
{
  public:
    CliError(ExitCode code, const std::string &what) : std::runtime_error(what), code_(code)
    {
    }
    ExitCode code() const noexcept
    {
        return code_;
    }

  private:
    ExitCode code_;
};

} // namespace ubii::cli

#endif
