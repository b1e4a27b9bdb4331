#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "test_port.h"
#include "ubii/config.h"
#include "ubii/port_linux.h"

namespace ubii_test
{

struct TestPort::Impl {
    ubii_linux_port *port = nullptr;
};

TestPort::TestPort(Tls tls) : impl_(std::make_unique<Impl>())
{
    ubii_linux_port_options options{};
    options.libwebsockets_log_level = 1;  // LLL_ERR: no notice per HTTP transaction
    options.enable_tls = tls != Tls::off; // only the TLS tests need it
    options.allow_self_signed = tls == Tls::allow_self_signed;
    if (tls == Tls::trust_test_ca) {
        options.ca_file = std::getenv("UBII_TEST_TLS_CA");
        if (options.ca_file == nullptr) {
            throw std::runtime_error("Tls::trust_test_ca needs UBII_TEST_TLS_CA");
        }
    }
    // The suite runs once per tcp:// engine (tests/CMakeLists.txt): the default, then libzmq.
    const char *engine = std::getenv("UBII_TEST_ZMQ_ENGINE");
    if (engine != nullptr && std::strcmp(engine, "libzmq") == 0) {
        options.zmq_engine = UBII_LINUX_ZMQ_LIBZMQ;
    } else if (engine != nullptr && engine[0] != '\0') {
        throw std::runtime_error(std::string("unknown UBII_TEST_ZMQ_ENGINE: ") + engine);
    }
    if (ubii_linux_port_create(&impl_->port, &options) != UBII_OK) {
        throw std::runtime_error("cannot create the Linux port");
    }
}

TestPort::~TestPort()
{
    ubii_linux_port_destroy(impl_->port);
}

ubii_port TestPort::get()
{
    return ubii_linux_port_get(impl_->port);
}

const char *TestPort::last_error() const
{
    return ubii_linux_port_last_error(impl_->port);
}

bool TestPort::supports_tls()
{
    return true;
}

size_t TestPort::max_message_size()
{
    return UBII_MAX_MESSAGE_SIZE; // the default of ubii_linux_port_options.max_message_size
}

} // namespace ubii_test
