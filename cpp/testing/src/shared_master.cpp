// The one master of a test program: installed (npm) when missing, started on first use in a
// private network or on free loopback ports, stopped when the program ends.
#include <dlfcn.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

#include "private_network.hpp"
#include "ubii/testing.hpp"
#include "ubii/version.h"

extern char **environ;

namespace ubii::testing
{

namespace
{

namespace fs = std::filesystem;

std::string environment(const char *name, const std::string &fallback = "")
{
    const char *value = std::getenv(name);
    return value != nullptr && *value != '\0' ? value : fallback;
}

// The project's scripts: UBII_TESTING_SCRIPTS, the installation's share/ubii/scripts (beside the
// libdir libubii was loaded from), or the source tree this library was built from.
fs::path scripts_directory()
{
    std::vector<fs::path> candidates;
    if (const std::string given = environment("UBII_TESTING_SCRIPTS"); !given.empty())
        candidates.emplace_back(given);
    Dl_info info{};
    if (dladdr(reinterpret_cast<void *>(&ubii_version), &info) != 0 && info.dli_fname != nullptr) {
        std::error_code error;
        const fs::path library = fs::canonical(info.dli_fname, error);
        if (!error)
            candidates.push_back(library.parent_path().parent_path() / "share" / "ubii" /
                                 "scripts");
    }
#ifdef UBII_TESTING_SOURCE_SCRIPTS
    candidates.emplace_back(UBII_TESTING_SOURCE_SCRIPTS);
#endif
    for (const fs::path &candidate : candidates)
        if (fs::exists(candidate / "master.sh"))
            return candidate;
    return {};
}

fs::path cache_directory()
{
    const std::string given = environment("UBII_CACHE_DIR");
    if (!given.empty())
        return given;
    const std::string xdg = environment("XDG_CACHE_HOME");
    return fs::path(xdg.empty() ? environment("HOME", "/tmp") + "/.cache" : xdg) / "libubii";
}

// Runs a command with its output in `log`; its exit code (-1 if it could not run).
int run_logged(const std::vector<std::string> &command, const fs::path &log)
{
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    std::vector<std::string> arguments = command;
    std::vector<char *> argv;
    for (std::string &argument : arguments)
        argv.push_back(argument.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string tail_of(const fs::path &log, std::size_t lines = 8)
{
    std::ifstream file(log);
    std::vector<std::string> all;
    for (std::string line; std::getline(file, line);)
        all.push_back(line);
    std::string text;
    for (std::size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i)
        text += "\n    " + all[i];
    return text;
}

bool port_free(int port)
{
    const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return false;
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_ANY); // the master binds every interface
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    const bool free = bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0;
    close(fd);
    return free;
}

// The first of four consecutive free ports, from a random start (two test programs at once pick
// different ones); 0 if none was found.
int free_port_base()
{
    std::random_device seed;
    std::mt19937 random(seed());
    std::uniform_int_distribution<int> start(20000, 60000);
    for (int attempt = 0; attempt < 50; ++attempt) {
        const int base = start(random);
        if (port_free(base) && port_free(base + 1) && port_free(base + 2) && port_free(base + 3))
            return base;
    }
    return 0;
}

class SharedMaster
{
  public:
    const MasterEndpoints *get(std::string *why)
    {
        std::call_once(started_, [this] { start(); });
        if (!running_)
            *why = why_;
        return running_ ? &endpoints_ : nullptr;
    }

    ~SharedMaster()
    {
        if (running_)
            run_logged({scripts_ / "master.sh", "stop", state_ / "master"}, state_ / "fixture.log");
        std::error_code ignored;
        if (!state_.empty() && environment("UBII_TESTING_KEEP_STATE") != "1")
            fs::remove_all(state_, ignored);
    }

  private:
    void start()
    {
        scripts_ = scripts_directory();
        if (scripts_.empty()) {
            why_ = "the master's scripts are not found (set UBII_TESTING_SCRIPTS to libubii's "
                   "scripts/ or install libubii)";
            return;
        }
        char state_template[] = "/tmp/ubii-testing-XXXXXX";
        if (mkdtemp(state_template) == nullptr) {
            why_ = "cannot make a state directory in /tmp";
            return;
        }
        state_ = state_template;
        const fs::path log = state_ / "fixture.log";
        const std::string source = environment("UBII_MASTER_SOURCE");
        const fs::path cache = cache_directory();
        // Installing needs the registry: before the private network, which reaches nothing.
        if (source.empty() && !fs::exists(cache / "npm" / "master" / ".ubii-stamp") &&
            run_logged({scripts_ / "npm-packages.sh", cache}, log) != 0) {
            why_ = "the master could not be installed (scripts/npm-packages.sh needs npm and the "
                   "npm registry):" +
                   tail_of(log);
            return;
        }
        std::string private_why;
        const bool wants_private = environment("UBII_TESTING_PRIVATE_NET", "1") != "0";
        endpoints_.private_network = wants_private && detail::enter_private_network(&private_why);
        if (wants_private && !endpoints_.private_network)
            std::ofstream(log, std::ios::app) << "no private network: " << private_why << '\n';
        setenv("UBII_CACHE_DIR", cache.c_str(), 1);
        const std::string fixed = environment("UBII_TESTING_PORT_BASE");
        for (int attempt = 0; attempt < 3 && !running_; ++attempt) {
            const int base = !fixed.empty()               ? std::atoi(fixed.c_str())
                             : endpoints_.private_network ? 8101
                                                          : free_port_base();
            if (base <= 0) {
                why_ = "no four consecutive free ports on loopback";
                return;
            }
            running_ = run_logged({scripts_ / "master.sh", "start", state_ / "master",
                                   std::to_string(base)},
                                  log) == 0;
            endpoints_.port_base = base;
            // The same ports again: a master of an earlier test program may still be releasing
            // them.
            if (!running_ && (!fixed.empty() || endpoints_.private_network))
                std::this_thread::sleep_for(std::chrono::seconds(1));
        }
        if (!running_) {
            why_ = "the master did not start (log in " + log.string() + "):" + tail_of(log);
            return;
        }
        const std::string host = "tcp://127.0.0.1:";
        endpoints_.service_url = host + std::to_string(endpoints_.port_base);
        endpoints_.topic_url = host + std::to_string(endpoints_.port_base + 2);
        endpoints_.websocket_url = "ws://127.0.0.1:" + std::to_string(endpoints_.port_base + 3);
        endpoints_.assigns_sessions = !source.empty();
    }

    std::once_flag started_;
    bool running_ = false;
    std::string why_;
    fs::path scripts_;
    fs::path state_;
    MasterEndpoints endpoints_;
};

SharedMaster &the_master()
{
    static SharedMaster master;
    return master;
}

} // namespace

const MasterEndpoints *shared_master(std::string *why)
{
    return the_master().get(why);
}

} // namespace ubii::testing
