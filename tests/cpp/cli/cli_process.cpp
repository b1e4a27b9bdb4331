#include "cli_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

extern char **environ;

namespace ubii_cli_test
{

Process::Process(const std::string &program, const std::vector<std::string> &arguments,
                 const std::vector<std::string> &environment)
{
    int out_pipe[2], err_pipe[2];
    if (pipe2(out_pipe, O_CLOEXEC) != 0 || pipe2(err_pipe, O_CLOEXEC) != 0)
        throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out_pipe[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err_pipe[1], STDERR_FILENO);
    std::vector<std::string> argv_text{program};
    argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
    std::vector<char *> argv;
    for (auto &argument : argv_text)
        argv.push_back(argument.data());
    argv.push_back(nullptr);
    std::vector<std::string> env_text;
    for (char **entry = environ; *entry != nullptr; ++entry)
        env_text.emplace_back(*entry);
    env_text.insert(env_text.end(), environment.begin(), environment.end());
    std::vector<char *> env;
    for (auto &entry : env_text)
        env.push_back(entry.data());
    env.push_back(nullptr);
    const int spawned =
        posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), env.data());
    posix_spawn_file_actions_destroy(&actions);
    close(out_pipe[1]);
    close(err_pipe[1]);
    out_fd_ = out_pipe[0];
    err_fd_ = err_pipe[0];
    if (spawned != 0)
        throw std::runtime_error("cannot start " + program);
}

Process::~Process()
{
    if (!exited_ && pid_ > 0) {
        kill(pid_, SIGKILL);
        waitpid(pid_, &status_, 0);
    }
    if (out_fd_ >= 0)
        close(out_fd_);
    if (err_fd_ >= 0)
        close(err_fd_);
}

bool Process::read_some(std::chrono::milliseconds timeout)
{
    pollfd fds[2] = {{out_fd_, POLLIN, 0}, {err_fd_, POLLIN, 0}};
    if (out_fd_ < 0 && err_fd_ < 0)
        return false;
    const int ready = poll(fds, 2, static_cast<int>(timeout.count()));
    if (ready <= 0)
        return true;
    int *fds_of[2] = {&out_fd_, &err_fd_};
    std::string *text_of[2] = {&out_, &err_};
    for (int i = 0; i < 2; ++i) {
        if (*fds_of[i] < 0 || fds[i].revents == 0)
            continue;
        char buffer[4096];
        const ssize_t got = read(*fds_of[i], buffer, sizeof buffer);
        if (got > 0) {
            text_of[i]->append(buffer, static_cast<std::size_t>(got));
        } else if (got == 0 || errno != EINTR) {
            close(*fds_of[i]);
            *fds_of[i] = -1;
        }
    }
    return true;
}

bool Process::read_until(const std::function<bool(const std::string &, const std::string &)> &done,
                         std::chrono::milliseconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done(out_, err_)) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0 || !read_some(std::min(left, std::chrono::milliseconds(100))))
            return done(out_, err_);
    }
    return true;
}

void Process::signal(int number)
{
    if (!exited_)
        kill(pid_, number);
}

Outcome Process::finish(std::chrono::milliseconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline && read_some(std::chrono::milliseconds(100)))
        ;
    while (!exited_) {
        const pid_t done = waitpid(pid_, &status_, WNOHANG);
        if (done == pid_) {
            exited_ = true;
            break;
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            kill(pid_, SIGKILL);
            waitpid(pid_, &status_, 0);
            exited_ = true;
            return Outcome{-1, out_, err_ + "\n[killed at the test's deadline]"};
        }
        usleep(10000);
    }
    return Outcome{WIFEXITED(status_) ? WEXITSTATUS(status_) : -1, out_, err_};
}

Outcome run(const std::string &program, const std::vector<std::string> &arguments,
            std::chrono::milliseconds timeout, const std::vector<std::string> &environment)
{
    Process process(program, arguments, environment);
    return process.finish(timeout);
}

} // namespace ubii_cli_test
