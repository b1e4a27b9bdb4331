// ocr_node: text recognition served over Ubi-Interact. Subscribes to Image2D records, recognises
// the newest one with the PURE, MSER or EAST pipeline and publishes the words as an Object2DList.
//
//   ocr_node [OPTIONS] pure|mser|east [EAST_MODEL]      (ocr_node --help; ocr/README.md)
//
// Exit status: 0 after SIGINT/SIGTERM, 1 when the pipeline or the connection cannot be set up,
// 2 for a bad command line.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "command_line.hpp"
#include "latest_frame.hpp"
#include "process_frame.hpp"
#include "stop_signal.hpp"
#include "ubii/ocr/error.hpp"
#include "ubii/ocr/omp.hpp"
#include "ubii/node.hpp"
#include "ubii/ocr/pipeline_factory.hpp"

namespace ocr_node
{
namespace
{

void print_line(const std::string &line)
{
    std::fputs(line.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

// Polls until the node is ready; false on timeout, failure or a stop signal.
bool wait_ready(ubii::Node &node, double timeout_s)
{
    const auto timeout = std::chrono::duration_cast<std::chrono::milliseconds>(
        std::chrono::duration<double>(timeout_s));
    return node.run_until(
               [&] {
                   return node.ready() || node.state() == ubii::ConnectionState::failed ||
                          stop_requested() != 0;
               },
               timeout) &&
           node.ready();
}

int run(const Settings &settings)
{
    // The pipeline first: a missing model or language file is reported before any connection.
    std::unique_ptr<ubii::ocr::Pipeline> pipeline;
    const std::string name(to_string(ubii::ocr::kind_of(settings.pipeline)));
    try {
        pipeline = ubii::ocr::make_pipeline(settings.pipeline);
    } catch (const std::exception &error) {
        std::fprintf(stderr, "ocr_node: cannot start the %s pipeline: %s\n", name.c_str(),
                     error.what());
        return 1;
    }

    ubii::NodeOptions options;
    options.service_url = settings.service_url;
    options.topic_url = settings.topic_url;
    options.name = "libubii-ocr-node";
    // Recognition keeps the polling thread busy for hundreds of milliseconds. libzmq's I/O thread
    // takes frames in meanwhile, so the next poll has the newest one and the stale ones are
    // dropped; the in-thread engine would leave them queued at the master, to be read in turn.
    options.zmq_engine = ubii::ZmqEngine::libzmq;
    options.libwebsockets_log_level = 1; // errors only
    ubii::Node node(options);
    node.on_error([](ubii::Status status, std::string_view detail) {
        std::fprintf(stderr, "ocr_node: %.*s (%s)\n", static_cast<int>(detail.size()),
                     detail.data(), ubii::describe(status));
    });
    node.on_state(
        [](ubii::ConnectionState previous, ubii::ConnectionState current, ubii::Status reason) {
            if (current == ubii::ConnectionState::reconnecting ||
                current == ubii::ConnectionState::failed)
                std::fprintf(stderr, "ocr_node: %s -> %s (%s)\n",
                             std::string(ubii::to_string(previous)).c_str(),
                             std::string(ubii::to_string(current)).c_str(), ubii::describe(reason));
        });

    try {
        node.start();
    } catch (const ubii::Error &error) {
        std::fprintf(stderr, "ocr_node: cannot connect to %s / %s: %s\n",
                     settings.service_url.c_str(), settings.topic_url.c_str(), error.what());
        return 1;
    }
    if (!wait_ready(node, settings.connect_timeout_s)) {
        if (stop_requested() != 0)
            return 0;
        const std::string transport = node.transport_error();
        std::fprintf(
            stderr, "ocr_node: the master at %s / %s was not reachable within %g s (node %s%s%s)\n",
            settings.service_url.c_str(), settings.topic_url.c_str(), settings.connect_timeout_s,
            std::string(ubii::to_string(node.state())).c_str(), transport.empty() ? "" : "; ",
            transport.c_str());
        return 1;
    }

    LatestFrame latest;
    ubii::Subscription frames_in;
    try {
        frames_in = node.subscribe(settings.input_topic, [&latest](const ubii::Record &record) {
            latest.on_record(record);
        });
    } catch (const ubii::Error &error) {
        std::fprintf(stderr, "ocr_node: cannot subscribe to %s: %s\n", settings.input_topic.c_str(),
                     error.what());
        return 1;
    }
    print_line("ocr_node: " + name + " pipeline ready, client " + node.client_id() + ", reading " +
               settings.input_topic + ", publishing " + settings.output_topic);

    // Poll, then recognise the newest frame the poll delivered (outside the callback).
    Frame frame;
    std::uint64_t frames = 0, failed = 0;
    while (stop_requested() == 0) {
        node.poll(std::chrono::milliseconds(100));
        if (!latest.take(frame))
            continue;
        const FrameResult result = process_frame(*pipeline, node.c_node(), settings.output_topic,
                                                 frame, ++frames, latest.dropped());
        failed += result.ok ? 0 : 1;
        if (!result.line.empty())
            print_line(result.line);
    }

    const bool confirmed = node.stop_wait();
    print_line("ocr_node: stopped (signal " + std::to_string(stop_requested()) +
               "): " + std::to_string(frames) + " frames, " + std::to_string(failed) + " failed, " +
               std::to_string(latest.dropped()) + " dropped of " +
               std::to_string(latest.received()) + " received");
    if (!confirmed)
        std::fprintf(stderr, "ocr_node: the master did not confirm the stop in %lld ms\n",
                     static_cast<long long>(options.stop_timeout.count()));
    return 0;
}

} // namespace
} // namespace ocr_node

int main(int argc, char **argv)
{
    // Before anything loads Tesseract: may re-execute the program with OMP_THREAD_LIMIT=1.
    if (!ubii::ocr::ensure_single_omp_thread(argc, argv))
        std::fprintf(stderr, "ocr_node: could not limit OpenMP to one thread; set "
                             "OMP_THREAD_LIMIT=1 for full speed\n");
    try {
        const ocr_node::Settings settings = ocr_node::parse_command_line(argc, argv);
        if (settings.help) {
            std::fputs(ocr_node::usage().c_str(), stdout);
            return 0;
        }
        ocr_node::catch_stop_signals();
        return ocr_node::run(settings);
    } catch (const ocr_node::UsageError &error) {
        std::fprintf(stderr, "ocr_node: %s (ocr_node --help)\n", error.what());
        return 2;
    } catch (const ubii::ocr::InvalidArgument &error) {
        std::fprintf(stderr, "ocr_node: %s (ocr_node --help)\n", error.what());
        return 2;
    } catch (const std::exception &error) {
        std::fprintf(stderr, "ocr_node: %s\n", error.what());
        return 1;
    }
}
