#ifndef UBII_TESTING_PRIVATE_NETWORK_HPP
#define UBII_TESTING_PRIVATE_NETWORK_HPP

#include <string>

namespace ubii::testing::detail
{

// Moves this process (its calling thread and every process and thread it starts from now on) into
// a new network namespace with only a loopback interface, up: as root directly, otherwise inside a
// new user namespace mapping this user to root. True if it is in one now (also when it already
// was: UBII_IN_PRIVATE_NET=1, set by scripts/private-net.sh and by this); false with `why` when
// the machine does not allow it (no user namespaces, a multi-threaded process, ...).
bool enter_private_network(std::string *why);

} // namespace ubii::testing::detail

#endif
