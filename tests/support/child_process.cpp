#include "child_process.h"

#include <csignal>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ubii_test
{

ChildProcess::ChildProcess(const std::vector<std::string> &argv)
{
    int pipe_fds[2];
    if (argv.empty() || pipe(pipe_fds) != 0) {
        return;
    }
    pid_ = fork();
    if (pid_ == 0) {
        dup2(pipe_fds[1], STDOUT_FILENO);
        close(pipe_fds[0]);
        close(pipe_fds[1]);
        std::vector<char *> args;
        for (const auto &arg : argv) {
            args.push_back(const_cast<char *>(arg.c_str()));
        }
        args.push_back(nullptr);
        execvp(args[0], args.data());
        _exit(127);
    }
    close(pipe_fds[1]);
    fd_ = pipe_fds[0];
    fcntl(fd_, F_SETFL, fcntl(fd_, F_GETFL) | O_NONBLOCK);
}

ChildProcess::~ChildProcess()
{
    if (pid_ > 0) {
        kill(pid_, SIGTERM);
        waitpid(pid_, nullptr, 0);
    }
    if (fd_ >= 0) {
        close(fd_);
    }
}

int ChildProcess::stop(int signal, std::chrono::milliseconds timeout)
{
    if (pid_ <= 0) {
        return -1;
    }
    kill(pid_, signal);
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    int status = 0;
    pid_t ended;
    while ((ended = waitpid(pid_, &status, WNOHANG)) == 0 &&
           std::chrono::steady_clock::now() < deadline) {
        usleep(10000);
    }
    if (ended == 0) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
    }
    pid_ = -1;
    return ended == 0 || !WIFEXITED(status) ? -1 : WEXITSTATUS(status);
}

std::vector<std::string> &ChildProcess::lines()
{
    char buffer[4096];
    ssize_t got;
    while (fd_ >= 0 && (got = read(fd_, buffer, sizeof buffer)) > 0) {
        partial_.append(buffer, static_cast<size_t>(got));
        size_t end;
        while ((end = partial_.find('\n')) != std::string::npos) {
            lines_.push_back(partial_.substr(0, end));
            partial_.erase(0, end + 1);
        }
    }
    return lines_;
}

} // namespace ubii_test
