#ifndef UBII_MODULE_REGISTRY_HPP
#define UBII_MODULE_REGISTRY_HPP

// ubii::ModuleRegistry: the processing modules a node can make by name, for sessions a master
// starts (Node::serve_sessions): a session names a module, the registry makes a fresh instance.
//
//     ubii::ModuleRegistry modules;
//     modules.add<Sum>();                              // a default-constructible module class
//     modules.add([] { return std::make_unique<Scale>(2.0); });
//     node.serve_sessions(modules);
//
// Each name is made by one factory; the spec offered to the master is taken from an instance the
// factory makes when added (its constructor runs then; on_created does not).

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ubii/messages.hpp"
#include "ubii/processing_module.hpp"

namespace ubii
{

using ModuleFactory = std::function<std::unique_ptr<ProcessingModule>()>;

class ModuleRegistry
{
  public:
    // ubii::InvalidArgument if the factory makes no module or one whose name is taken; what the
    // factory throws propagates.
    void add(ModuleFactory factory);
    template <class M> void add()
    {
        add([] { return std::make_unique<M>(); });
    }

    bool contains(std::string_view name) const noexcept;
    bool empty() const noexcept
    {
        return entries_.empty();
    }
    std::vector<std::string> names() const;
    // The specs of every module, as the master is told (language CPP, no ids).
    std::vector<ProcessingModuleSpec> specs() const;
    // A fresh instance of the module `name`: ubii::NotFound for a name not here; what the factory
    // throws propagates; ubii::InvalidArgument if it made another module than its name says.
    std::unique_ptr<ProcessingModule> create(std::string_view name) const;

  private:
    struct Entry {
        ModuleFactory factory;
        ProcessingModuleSpec spec;
    };
    std::map<std::string, Entry, std::less<>> entries_;
};

} // namespace ubii

#endif
