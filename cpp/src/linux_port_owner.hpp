#ifndef UBII_CPP_LINUX_PORT_OWNER_HPP
#define UBII_CPP_LINUX_PORT_OWNER_HPP

// The Linux port a ubii::Node creates for itself when it is given none.

#include <memory>
#include <string>

#include "ubii/node_options.hpp"
#include "ubii/port.h"

namespace ubii::detail
{

class LinuxPortOwner
{
  public:
    // ubii::TransportError if the port cannot start; ubii::Unsupported in a build without it.
    explicit LinuxPortOwner(const NodeOptions &options);
    ~LinuxPortOwner();
    LinuxPortOwner(const LinuxPortOwner &) = delete;
    LinuxPortOwner &operator=(const LinuxPortOwner &) = delete;

    ubii_port port() const noexcept
    {
        return port_;
    }
    // The port's last transport failure ("" if none).
    std::string last_error() const;
    // Ends a wait of the port's poll at once; callable from any thread.
    void wake() noexcept;

  private:
    struct Handle;
    std::unique_ptr<Handle> handle_;
    ubii_port port_{};
};

} // namespace ubii::detail

#endif
