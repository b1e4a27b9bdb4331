#ifndef UBII_STANDALONE_MODULE_HPP
#define UBII_STANDALONE_MODULE_HPP

// ubii::StandaloneModule: one processing module run without a node, on records handed to it, in a
// scheduler of its own that the calling thread drives; for tools that apply a module to files
// (`ubii-node ocr`), for tests and benchmarks of a module, for an engine that feeds it directly.
//
//     ubii::StandaloneModule ocr(registry.create("TesseractOCR_PURE"));
//     std::optional<ubii::PassOutput> words;
//     ocr.scheduler().on_output([&](const ubii::ProcessingModule &, const ubii::PassOutput &out) {
//         words = out; return ubii::Status::ok; });
//     ocr.feed("image", std::make_shared<const ubii::Record>("image", image));
//     ocr.run_until([&] { return words.has_value(); }, std::chrono::seconds(10));
//
// Passes on the worker executor run on the module's thread; run_until sleeps until one ends and
// hands its outputs on in the calling thread, like a node's poll.

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "ubii/processing_module.hpp"
#include "ubii/scheduler.hpp"

namespace ubii
{

class StandaloneModule
{
  public:
    // Creates the module (on_created: what it throws propagates) and starts it.
    explicit StandaloneModule(std::unique_ptr<ProcessingModule> module);
    // Halts and destroys the module (a worker pass in flight ends first).
    ~StandaloneModule();
    StandaloneModule(const StandaloneModule &) = delete;
    StandaloneModule &operator=(const StandaloneModule &) = delete;

    // Set its output sink, error and log handlers here; the waker is this object's.
    Scheduler &scheduler() noexcept
    {
        return scheduler_;
    }
    const std::string &id() const noexcept
    {
        return id_;
    }
    Timing timing() const
    {
        return scheduler_.timing(id_);
    }

    // A record for `input` (latest wins, as in a node), then whatever is due runs.
    void feed(std::string_view input, std::shared_ptr<const Record> record);
    // Runs passes and hands on their outputs until `done()` holds (checked after each round) or
    // `timeout` passes; whether it held.
    bool run_until(const std::function<bool()> &done, std::chrono::nanoseconds timeout);

  private:
    Scheduler scheduler_;
    std::string id_;
    std::mutex mutex_;
    std::condition_variable woken_;
    bool pass_ended_ = false;
};

} // namespace ubii

#endif
