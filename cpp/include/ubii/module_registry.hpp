#ifndef UBII_MODULE_REGISTRY_HPP
#define UBII_MODULE_REGISTRY_HPP

// ubii::ModuleRegistry: the processing modules a node can make by name, for sessions a master
// starts (Node::serve_sessions): a session names a module, the registry makes a fresh instance.
//
//     ubii::ModuleRegistry modules;
//     modules.add<Sum>();                              // default-constructible, or from arguments
//     modules.add([] { return std::make_unique<Scale>(2.0); });
//     modules.add([](const ubii::ModuleArguments &args) {
//         return std::make_unique<Scale>(args.get("factor", 2.0));
//     });
//     modules.configure("scale", {{"factor", "0.5"}});
//     node.serve_sessions(modules);
//
// Each name is made by one factory; the spec offered to the master is taken from an instance the
// factory makes when added, with no arguments (its constructor runs then; on_created does not),
// and again when the name is configured. Modules come from here, from UBII_REGISTER_MODULE in the
// program itself and from plugins (ubii/module_discovery.hpp).

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "ubii/messages.hpp"
#include "ubii/module_arguments.hpp"
#include "ubii/processing_module.hpp"

namespace ubii
{

using ModuleFactory = std::function<std::unique_ptr<ProcessingModule>(const ModuleArguments &)>;

// The factory of module class M: M(const ModuleArguments &) where M has that constructor, else M().
template <class M> ModuleFactory module_factory()
{
    static_assert(std::is_base_of_v<ProcessingModule, M>, "not a ubii::ProcessingModule");
    return [](const ModuleArguments &arguments) -> std::unique_ptr<ProcessingModule> {
        if constexpr (std::is_constructible_v<M, const ModuleArguments &>)
            return std::make_unique<M>(arguments);
        else
            return std::make_unique<M>();
    };
}

class ModuleRegistry
{
  public:
    // Returns the module's name. ubii::InvalidArgument if the factory makes no module or one whose
    // name is taken; what the factory throws propagates (the registry is unchanged then).
    const std::string &add(ModuleFactory factory);
    // A factory that takes no arguments.
    template <class F, std::enable_if_t<std::is_invocable_v<F &> &&
                                            !std::is_invocable_v<F &, const ModuleArguments &>,
                                        int> = 0>
    const std::string &add(F factory)
    {
        return add(ModuleFactory([factory = std::move(factory)](const ModuleArguments &) mutable
                                 -> std::unique_ptr<ProcessingModule> { return factory(); }));
    }
    template <class M> const std::string &add()
    {
        return add(module_factory<M>());
    }

    // The arguments module `name` is made with from now on. Makes one with them first: what its
    // factory throws propagates (a value it refuses), ubii::InvalidArgument for arguments it did
    // not read, ubii::NotFound for a name not here; the registry is unchanged then.
    void configure(std::string_view name, ModuleArguments arguments);
    // ubii::NotFound for a name not here.
    const ModuleArguments &arguments(std::string_view name) const;

    bool contains(std::string_view name) const noexcept;
    bool empty() const noexcept
    {
        return entries_.empty();
    }
    std::size_t size() const noexcept
    {
        return entries_.size();
    }
    std::vector<std::string> names() const;
    // The specs of every module, as the master is told (language CPP, no ids).
    std::vector<ProcessingModuleSpec> specs() const;
    // ubii::NotFound for a name not here.
    const ProcessingModuleSpec &spec(std::string_view name) const;
    // Keeps only the modules named (ubii::NotFound, naming it, for a name not here; nothing is
    // removed then).
    void retain(const std::vector<std::string> &names);
    // A fresh instance of the module `name` made with its arguments: ubii::NotFound for a name not
    // here; what the factory throws propagates; ubii::InvalidArgument if it made another module
    // than its name says.
    std::unique_ptr<ProcessingModule> create(std::string_view name) const;

  private:
    struct Entry {
        ModuleFactory factory;
        ProcessingModuleSpec spec;
        ModuleArguments arguments;
    };
    const Entry &entry(std::string_view name) const;
    std::unique_ptr<ProcessingModule> make(std::string_view name, const Entry &entry,
                                           const ModuleArguments &arguments) const;

    std::map<std::string, Entry, std::less<>> entries_;
};

} // namespace ubii

#endif
