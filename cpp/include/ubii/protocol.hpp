#ifndef UBII_PROTOCOL_HPP
#define UBII_PROTOCOL_HPP

// ubii::Protocol<State>: an explicit state machine, the C++ form of the thesis's node protocols
// (§2.3.2). It knows its states' names, which transitions are allowed, and runs hooks on them.
// A hook can hold the step it belongs to open (Transition::hold()) until asynchronous work is done,
// e.g. registering devices before a node counts as ready; settled() says when every hold is gone.
// The node's connection lifecycle is one (ConnectionState, ubii/node.hpp), the processing module
// lifecycle reuses it.
//
//     ubii::Protocol<Light> light("light", Light::off, {{Light::off, Light::on}, {Light::on,
//     Light::off}},
//                                 light_name);
//     light.on_enter(Light::on, [](ubii::Transition<Light> &t) { ... });
//     light.transition(Light::on);        // ubii::StateError for a transition not allowed
//
// Single-threaded. A transition asked for inside a hook runs after the current one's hooks.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ubii/error.hpp"

namespace ubii
{

// Keeps a protocol step unsettled until released (or destroyed). Movable, not copyable.
class Hold
{
  public:
    Hold() = default;
    explicit Hold(const std::shared_ptr<std::size_t> &count) : count_(count)
    {
        ++*count;
    }
    Hold(Hold &&other) noexcept : count_(std::move(other.count_))
    {
        other.count_.reset();
    }
    Hold &operator=(Hold &&other) noexcept
    {
        if (this != &other) {
            release();
            count_ = std::move(other.count_);
            other.count_.reset();
        }
        return *this;
    }
    Hold(const Hold &) = delete;
    Hold &operator=(const Hold &) = delete;
    ~Hold()
    {
        release();
    }
    // Lets the step settle; a hold of a step the protocol has since left is released silently.
    void release() noexcept
    {
        if (auto count = count_.lock())
            --*count;
        count_.reset();
    }
    bool active() const noexcept
    {
        return !count_.expired();
    }

  private:
    std::weak_ptr<std::size_t> count_;
};

template <class State> class Transition
{
  public:
    Transition(State from, State to, std::shared_ptr<std::size_t> holds)
        : from_(from), to_(to), holds_(std::move(holds))
    {
    }
    State from() const noexcept
    {
        return from_;
    }
    State to() const noexcept
    {
        return to_;
    }
    // Keeps the step into to() unsettled until the returned Hold is released.
    Hold hold()
    {
        return Hold(holds_);
    }

  private:
    State from_, to_;
    std::shared_ptr<std::size_t> holds_;
};

template <class State> class Protocol
{
  public:
    using Hook = std::function<void(Transition<State> &)>;
    using HookId = std::uint64_t;
    using Names = std::string_view (*)(State);
    // Called with a hook's exception (the transition itself stands); without one, the first
    // exception is rethrown from transition() after every hook has run.
    using ErrorHandler = std::function<void(std::exception_ptr, const Transition<State> &)>;

    Protocol(std::string name, State initial, std::vector<std::pair<State, State>> allowed,
             Names names)
        : name_(std::move(name)), state_(initial), allowed_(std::move(allowed)), names_(names),
          holds_(std::make_shared<std::size_t>(0))
    {
    }

    const std::string &name() const noexcept
    {
        return name_;
    }
    State state() const noexcept
    {
        return state_;
    }
    std::string_view state_name(State state) const
    {
        return names_(state);
    }
    bool allows(State from, State to) const noexcept
    {
        return std::find(allowed_.begin(), allowed_.end(), std::make_pair(from, to)) !=
               allowed_.end();
    }
    // Whether no hook holds the step into the current state open.
    bool settled() const noexcept
    {
        return *holds_ == 0;
    }

    // Hooks run in this order: on_transition(from, to), on_enter(to), on_every_transition.
    HookId on_transition(State from, State to, Hook hook)
    {
        return add(from, to, std::move(hook));
    }
    HookId on_enter(State to, Hook hook)
    {
        return add(std::nullopt, to, std::move(hook));
    }
    HookId on_every_transition(Hook hook)
    {
        return add(std::nullopt, std::nullopt, std::move(hook));
    }
    void remove_hook(HookId id)
    {
        hooks_.erase(std::remove_if(hooks_.begin(), hooks_.end(),
                                    [id](const Entry &entry) { return entry.id == id; }),
                     hooks_.end());
    }
    void set_error_handler(ErrorHandler handler)
    {
        error_handler_ = std::move(handler);
    }

    // Moves to `to` and runs its hooks: ubii::StateError if the transition is not allowed.
    void transition(State to)
    {
        const State from = last_queued();
        if (!allows(from, to))
            throw StateError(name_ + ": no transition from " + std::string(names_(from)) + " to " +
                             std::string(names_(to)));
        enqueue(to);
    }
    // Moves to `to` whether or not the table allows it (for a state machine that mirrors another
    // one, whose word is final), running its hooks.
    void force(State to)
    {
        enqueue(to);
    }

  private:
    struct Entry {
        HookId id;
        std::optional<State> from;
        std::optional<State> to;
        Hook hook;
    };

    HookId add(std::optional<State> from, std::optional<State> to, Hook hook)
    {
        hooks_.push_back(Entry{++last_id_, from, to, std::move(hook)});
        return last_id_;
    }
    State last_queued() const
    {
        return pending_.empty() ? state_ : pending_.back();
    }
    void enqueue(State to)
    {
        pending_.push_back(to);
        if (running_)
            return;
        running_ = true;
        std::exception_ptr first;
        while (!pending_.empty()) {
            const State next = pending_.front();
            pending_.pop_front();
            run(next, first);
        }
        running_ = false;
        if (first)
            std::rethrow_exception(first);
    }
    void run(State to, std::exception_ptr &first)
    {
        const State from = state_;
        state_ = to;
        holds_ = std::make_shared<std::size_t>(0); // holds of the step left are void
        Transition<State> transition(from, to, holds_);
        // A copy: a hook may add or remove hooks.
        const std::vector<Entry> hooks = ordered(from, to);
        for (const Entry &entry : hooks) {
            try {
                entry.hook(transition);
            } catch (...) {
                if (error_handler_)
                    error_handler_(std::current_exception(), transition);
                else if (!first)
                    first = std::current_exception();
            }
        }
    }
    std::vector<Entry> ordered(State from, State to) const
    {
        std::vector<Entry> result;
        for (const Entry &entry : hooks_)
            if (entry.from && *entry.from == from && entry.to && *entry.to == to)
                result.push_back(entry);
        for (const Entry &entry : hooks_)
            if (!entry.from && entry.to && *entry.to == to)
                result.push_back(entry);
        for (const Entry &entry : hooks_)
            if (!entry.from && !entry.to)
                result.push_back(entry);
        return result;
    }

    std::string name_;
    State state_;
    std::vector<std::pair<State, State>> allowed_;
    Names names_;
    std::shared_ptr<std::size_t> holds_;
    std::vector<Entry> hooks_;
    HookId last_id_ = 0;
    ErrorHandler error_handler_;
    std::deque<State> pending_;
    bool running_ = false;
};

} // namespace ubii

#endif
