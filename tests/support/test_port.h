#ifndef UBII_TEST_PORT_H
#define UBII_TEST_PORT_H

// The port the tests run on: the build's UBII_PORT (Linux or embedded), behind one small class so
// that one integration suite serves both.

#include <cstddef>
#include <memory>

#include "ubii/port.h"

namespace ubii_test
{

// How the port handles wss:// and https:// (the embedded port has no TLS). trust_test_ca: only the
// certificates in the file UBII_TEST_TLS_CA names (the TLS master's own, tests/CMakeLists.txt).
enum class Tls { off, strict, allow_self_signed, trust_test_ca };

class TestPort
{
  public:
    explicit TestPort(Tls tls = Tls::off);
    ~TestPort();
    TestPort(const TestPort &) = delete;
    TestPort &operator=(const TestPort &) = delete;

    ubii_port get();
    const char *last_error() const;
    static bool supports_tls();
    // Largest message the port takes or accepts (its buffers on the embedded port).
    static size_t max_message_size();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace ubii_test

#endif
