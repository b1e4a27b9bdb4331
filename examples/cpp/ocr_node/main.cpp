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
#include "ubii/ocr/pipeline_factory.hpp"
#include "ubii_owners.hpp"

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

// Node callbacks (C ABI): print only.
void on_error(ubii_node *, ubii_status status, const char *detail, void *)
{
    std::fprintf(stderr, "ocr_node: %s (%s)\n", detail, ubii_strerror(status));
}

void on_state(ubii_node *, ubii_state previous, ubii_state current, ubii_status reason, void *)
{
    if (current == UBII_STATE_RECONNECTING || current == UBII_STATE_FAILED)
        std::fprintf(stderr, "ocr_node: %s -> %s (%s)\n", ubii_state_name(previous),
                     ubii_state_name(current), ubii_strerror(reason));
}

// Polls until the node is READY; false on timeout, FAILED or a stop signal.
bool wait_ready(Node &node, double timeout_s)
{
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(timeout_s));
    while (node.state() != UBII_STATE_READY) {
        if (stop_requested() != 0 || node.state() == UBII_STATE_FAILED ||
            std::chrono::steady_clock::now() >= deadline)
            return false;
        ubii_node_poll(node.get(), 50);
    }
    return true;
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

    const LinuxPort port = make_linux_port();
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = settings.service_url.c_str();
    config.topic_url = settings.topic_url.c_str();
    config.client_name = "libubii-ocr-node";
    config.on_error = on_error;
    config.on_state = on_state;
    Node node(config, ubii_linux_port_get(port.get()));

    ubii_status status = ubii_node_start(node.get());
    if (status != UBII_OK) {
        std::fprintf(stderr, "ocr_node: cannot connect to %s / %s: %s\n",
                     settings.service_url.c_str(), settings.topic_url.c_str(),
                     ubii_strerror(status));
        return 1;
    }
    if (!wait_ready(node, settings.connect_timeout_s)) {
        if (stop_requested() != 0)
            return 0;
        std::fprintf(
            stderr, "ocr_node: the master at %s / %s was not reachable within %g s (node %s%s%s)\n",
            settings.service_url.c_str(), settings.topic_url.c_str(), settings.connect_timeout_s,
            ubii_state_name(node.state()),
            *ubii_linux_port_last_error(port.get()) != '\0' ? "; " : "",
            ubii_linux_port_last_error(port.get()));
        return 1;
    }

    LatestFrame latest;
    status = ubii_subscribe(node.get(), settings.input_topic.c_str(), LatestFrame::on_record,
                            &latest, nullptr);
    if (status != UBII_OK) {
        std::fprintf(stderr, "ocr_node: cannot subscribe to %s: %s\n", settings.input_topic.c_str(),
                     ubii_strerror(status));
        return 1;
    }
    print_line("ocr_node: " + name + " pipeline ready, client " + ubii_node_client_id(node.get()) +
               ", reading " + settings.input_topic + ", publishing " + settings.output_topic);

    // Poll, then recognise the newest frame the poll delivered (outside the callback).
    Frame frame;
    std::uint64_t frames = 0, failed = 0;
    while (stop_requested() == 0) {
        ubii_node_poll(node.get(), 100);
        if (!latest.take(frame))
            continue;
        const FrameResult result = process_frame(*pipeline, node.get(), settings.output_topic,
                                                 frame, ++frames, latest.dropped());
        failed += result.ok ? 0 : 1;
        if (!result.line.empty())
            print_line(result.line);
    }

    status = node.stop();
    print_line("ocr_node: stopped (signal " + std::to_string(stop_requested()) +
               "): " + std::to_string(frames) + " frames, " + std::to_string(failed) + " failed, " +
               std::to_string(latest.dropped()) + " dropped of " +
               std::to_string(latest.received()) + " received");
    if (status != UBII_OK)
        std::fprintf(stderr, "ocr_node: the master did not confirm the stop in %d ms (%s)\n",
                     Node::stop_timeout_ms, ubii_strerror(status));
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
