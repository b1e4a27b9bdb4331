#include "test_port.h"
#include "ubii/port_embedded.h"

namespace ubii_test
{

struct TestPort::Impl {
    ubii_embedded_port port;
};

TestPort::TestPort(Tls) : impl_(std::make_unique<Impl>())
{
    ubii_embedded_port_init(&impl_->port, ubii_embedded_posix_platform());
}

TestPort::~TestPort()
{
    ubii_embedded_port_close(&impl_->port);
}

ubii_port TestPort::get()
{
    return ubii_embedded_port_get(&impl_->port);
}

const char *TestPort::last_error() const
{
    return ubii_embedded_port_last_error(&impl_->port);
}

bool TestPort::supports_tls()
{
    return false;
}

size_t TestPort::max_message_size()
{
    return UBII_EMBEDDED_MAX_MESSAGE;
}

} // namespace ubii_test
