// session: a master assigns a processing module to a node. A "worker" node offers Celsius (a
// module turning Fahrenheit into Celsius) as a dedicated processing node; a "control" client
// starts a session that maps /thermo/fahrenheit to the module's input and its output to
// /thermo/celsius, publishes readings and prints the converted values that come back; then it
// stops the session, and the worker reports its module removed.
//
// Needs a master that assigns modules to nodes: the current master (scripts/current-master.sh);
// the npm 0.4.0 master runs every session module itself and never tells a node.
//
//   session_cpp [SERVICE_URL [TOPIC_URL]]   defaults: tcp://127.0.0.1:8101 tcp://127.0.0.1:8103
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ubii/ubii.hpp"

using namespace std::chrono_literals;

namespace
{

class Celsius : public ubii::ProcessingModule
{
  public:
    Celsius()
        : ProcessingModule({"fahrenheit_to_celsius",
                            "converts temperatures",
                            {ubii::input<double>("fahrenheit")},
                            {ubii::output<double>("celsius")},
                            ubii::TriggerOnInput{}})
    {
    }

  protected:
    void on_processing(ubii::Pass &pass) override
    {
        pass.set_output("celsius", (pass.input<double>("fahrenheit") - 32) * 5 / 9);
    }
};

// The session as a client writes it: modules by name, their mappings by module name; the master
// assigns the module to a node offering it and fills in the ids.
ubii::Session conversion_session()
{
    ubii::Session session;
    session.set_name("thermometer");
    session.add_processing_modules()->set_name("fahrenheit_to_celsius");
    ubii::IOMapping &mapping = *session.add_io_mappings();
    mapping.set_processing_module_name("fahrenheit_to_celsius");
    auto &input = *mapping.add_input_mappings();
    input.set_input_name("fahrenheit");
    input.set_topic("/thermo/fahrenheit");
    auto &output = *mapping.add_output_mappings();
    output.set_output_name("celsius");
    output.set_topic("/thermo/celsius");
    return session;
}

} // namespace

int main(int argc, char **argv)
{
    ubii::NodeOptions options;
    options.service_url = argc > 1 ? argv[1] : "tcp://127.0.0.1:8101";
    options.topic_url = argc > 2 ? argv[2] : "tcp://127.0.0.1:8103";
    try {
        ubii::NodeOptions worker_options = options;
        worker_options.name = "session-worker";
        worker_options.is_dedicated_processing_node = true;
        ubii::Node worker(worker_options);
        worker.on_session_event([](const ubii::SessionEvent &event) {
            std::printf("worker: %s %s (session %s)%s%s\n",
                        std::string(to_string(event.kind)).c_str(), event.module_name.c_str(),
                        event.session_id.c_str(), event.detail.empty() ? "" : ": ",
                        event.detail.c_str());
        });
        ubii::ModuleRegistry modules;
        modules.add<Celsius>();
        worker.serve_sessions(std::move(modules));
        worker.connect(10s);

        ubii::NodeOptions control_options = options;
        control_options.name = "session-control";
        ubii::Node control(control_options);
        control.connect(10s);
        std::vector<double> celsius;
        auto subscription = control.subscribe<double>(
            "/thermo/celsius",
            [&](double value, const ubii::RecordInfo &) { celsius.push_back(value); });

        const auto poll_both = [&](const auto &done, std::chrono::milliseconds timeout) {
            const auto until = std::chrono::steady_clock::now() + timeout;
            while (!done() && std::chrono::steady_clock::now() < until) {
                worker.poll(5ms);
                control.poll(5ms);
            }
            return done();
        };

        auto started = control.sessions().start(conversion_session());
        if (!poll_both([&] { return started.done(); }, 10s))
            throw ubii::Timeout("the master did not answer the session start");
        const ubii::Session session = started.get();
        std::printf("control: session %s started\n", session.id().c_str());
        if (!poll_both([&] { return !worker.session_modules().empty(); }, 10s))
            throw ubii::Timeout(
                "the master assigned the module to no node (is it the current master?)");

        // Each reading until its conversion arrives (the first may precede the master's
        // forwarding to the module by a moment).
        for (double reading : {32.0, 98.6, 212.0}) {
            const double expected = (reading - 32) * 5 / 9;
            auto next_publish = std::chrono::steady_clock::now();
            if (!poll_both(
                    [&] {
                        if (std::chrono::steady_clock::now() >= next_publish) {
                            control.publish("/thermo/fahrenheit", reading);
                            next_publish += 500ms;
                        }
                        return !celsius.empty() && std::abs(celsius.back() - expected) < 1e-9;
                    },
                    5s))
                throw ubii::Timeout("no converted value came back");
            std::printf("control: %.1f F -> %.1f C\n", reading, celsius.back());
        }

        auto stopped = control.sessions().stop(session.id());
        poll_both([&] { return stopped.done() && worker.session_modules().empty(); }, 10s);
        if (!worker.session_modules().empty())
            throw ubii::StateError("the module still runs after the session stopped");
        std::printf("control: session stopped; the worker runs %zu modules\n",
                    worker.session_modules().size());
        poll_both([] { return false; }, 300ms); // the worker's removal report
        return 0;
    } catch (const std::exception &error) {
        std::fprintf(stderr, "session_cpp: %s\n", error.what());
        return 1;
    }
}
