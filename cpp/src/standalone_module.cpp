#include "ubii/standalone_module.hpp"

#include <algorithm>

namespace ubii
{

StandaloneModule::StandaloneModule(std::unique_ptr<ProcessingModule> module)
{
    scheduler_.set_waker([this] {
        const std::lock_guard<std::mutex> lock(mutex_);
        pass_ended_ = true;
        woken_.notify_one();
    });
    id_ = scheduler_.add(std::move(module));
    scheduler_.start(id_);
}

StandaloneModule::~StandaloneModule()
{
    scheduler_.remove(id_);
}

void StandaloneModule::feed(std::string_view input, std::shared_ptr<const Record> record)
{
    scheduler_.feed(id_, input, std::move(record));
    scheduler_.run_due();
}

bool StandaloneModule::run_until(const std::function<bool()> &done,
                                 std::chrono::nanoseconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        scheduler_.run_due();
        if (done())
            return true;
        // Until a worker pass ends, or the next pass of a timed mode is due.
        auto wake_at = deadline;
        if (const auto due = scheduler_.next_due()) {
            const auto until_due = *due - scheduler_.clock().now();
            wake_at = std::min(wake_at, std::chrono::steady_clock::now() +
                                            std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                std::max(until_due, Clock::duration::zero())));
        }
        std::unique_lock<std::mutex> lock(mutex_);
        woken_.wait_until(lock, wake_at, [this] { return pass_ended_; });
        pass_ended_ = false;
        if (std::chrono::steady_clock::now() >= deadline) {
            lock.unlock();
            scheduler_.run_due();
            return done();
        }
    }
}

} // namespace ubii
