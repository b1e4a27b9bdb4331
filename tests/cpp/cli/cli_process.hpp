#ifndef UBII_TEST_CLI_PROCESS_HPP
#define UBII_TEST_CLI_PROCESS_HPP

// The ubii-node binary as the CLI tests run it: a child process whose stdout and stderr are read
// while it runs, with a deadline after which it is killed (a hang is a failure, never a stuck
// test).

#include <sys/types.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace ubii_cli_test
{

struct Outcome {
    int exit_code = -1; // -1: killed at the deadline or by a signal
    std::string out;
    std::string err;
};

class Process
{
  public:
    // Starts `program` with `arguments`; `environment` entries ("NAME=value") are added to ours.
    Process(const std::string &program, const std::vector<std::string> &arguments,
            const std::vector<std::string> &environment = {});
    ~Process();
    Process(const Process &) = delete;
    Process &operator=(const Process &) = delete;

    // Reads output until `done(out, err)` holds or `timeout` passes; whether it held.
    bool read_until(const std::function<bool(const std::string &, const std::string &)> &done,
                    std::chrono::milliseconds timeout);
    void signal(int number);
    // Waits for the exit (killing it after `timeout`), with everything it printed.
    Outcome finish(std::chrono::milliseconds timeout);
    const std::string &out() const
    {
        return out_;
    }
    const std::string &err() const
    {
        return err_;
    }

  private:
    // Reads what is there within `timeout`; false once both pipes are closed.
    bool read_some(std::chrono::milliseconds timeout);

    pid_t pid_ = -1;
    int out_fd_ = -1;
    int err_fd_ = -1;
    std::string out_;
    std::string err_;
    bool exited_ = false;
    int status_ = 0;
};

// Runs it to the end (at most `timeout`).
Outcome run(const std::string &program, const std::vector<std::string> &arguments,
            std::chrono::milliseconds timeout = std::chrono::seconds(30),
            const std::vector<std::string> &environment = {});

} // namespace ubii_cli_test

#endif
