#ifndef UBII_TEST_CHILD_PROCESS_H
#define UBII_TEST_CHILD_PROCESS_H

// Runs a program with its stdout on a non-blocking pipe, so a test can read its lines while it
// keeps polling a node. The child is killed when the object goes.

#include <chrono>
#include <signal.h>
#include <string>
#include <vector>

#include <sys/types.h>

namespace ubii_test
{

class ChildProcess
{
  public:
    explicit ChildProcess(const std::vector<std::string> &argv);
    ~ChildProcess();
    ChildProcess(const ChildProcess &) = delete;
    ChildProcess &operator=(const ChildProcess &) = delete;

    bool started() const
    {
        return pid_ > 0;
    }
    // Sends `signal` and waits up to `timeout` for the child to end. Returns its exit status, or
    // -1 if it ended by a signal or did not end in time (it is then killed). Its output stays
    // readable through lines().
    int stop(int signal, std::chrono::milliseconds timeout);
    // Sends `signal` and lets the child run on.
    void signal(int number) const
    {
        if (pid_ > 0) {
            ::kill(pid_, number);
        }
    }
    // Complete lines read so far (without the newline); reads what is available, never blocks.
    std::vector<std::string> &lines();

  private:
    pid_t pid_ = -1;
    int fd_ = -1;
    std::string partial_;
    std::vector<std::string> lines_;
};

} // namespace ubii_test

#endif
