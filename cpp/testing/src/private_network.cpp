#include "private_network.hpp"

#include <fcntl.h>
#include <net/if.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace ubii::testing::detail
{

namespace
{

bool write_file(const char *path, const std::string &text)
{
    std::ofstream file(path);
    file << text;
    file.flush();
    return static_cast<bool>(file);
}

bool fail(std::string *why, const std::string &what)
{
    *why = what + ": " + std::strerror(errno);
    return false;
}

bool loopback_up(std::string *why)
{
    const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return fail(why, "socket");
    ifreq request{};
    std::strncpy(request.ifr_name, "lo", IFNAMSIZ - 1);
    bool up = ioctl(fd, SIOCGIFFLAGS, &request) == 0;
    if (up) {
        request.ifr_flags = static_cast<short>(request.ifr_flags | IFF_UP);
        up = ioctl(fd, SIOCSIFFLAGS, &request) == 0;
    }
    const int error = errno;
    close(fd);
    errno = error;
    return up || fail(why, "bringing the loopback interface up");
}

} // namespace

bool enter_private_network(std::string *why)
{
    const char *inside = std::getenv("UBII_IN_PRIVATE_NET");
    if (inside != nullptr && std::string(inside) == "1")
        return true;
    if (geteuid() == 0) {
        if (unshare(CLONE_NEWNET) != 0)
            return fail(why, "unshare(CLONE_NEWNET)");
    } else {
        const uid_t uid = getuid();
        const gid_t gid = getgid();
        if (unshare(CLONE_NEWUSER | CLONE_NEWNET) != 0)
            return fail(why, "unshare(CLONE_NEWUSER | CLONE_NEWNET)");
        // Without these the process would be nobody inside, unable to configure the interface.
        if (!write_file("/proc/self/setgroups", "deny") ||
            !write_file("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1") ||
            !write_file("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1"))
            return fail(why, "mapping the user into the new user namespace");
    }
    if (!loopback_up(why))
        return false;
    setenv("UBII_IN_PRIVATE_NET", "1", 1);
    return true;
}

} // namespace ubii::testing::detail
