#ifndef UBII_TEST_LOOPBACK_H
#define UBII_TEST_LOOPBACK_H

// A TCP listener on 127.0.0.1 at a port the kernel picks, for hand-written peers in tests.

#include <cstdint>

namespace ubii_test
{

// The listening socket (backlog 1), or -1; its port goes to `port`.
int listen_on_loopback(uint16_t &port);

} // namespace ubii_test

#endif
