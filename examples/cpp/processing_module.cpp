// processing_module: a processing module wired to topics. A "tracker" node publishes a hand
// position moving on a circle at 100 Hz; the "processing" node runs Speed, a module that turns
// positions into a speed, triggered by its input at most every 20 ms, and publishes it; the
// example prints the speeds that arrive and the module's timing metric.
//
//   processing_module_cpp [SERVICE_URL [TOPIC_URL [SECONDS]]]   defaults: tcp://127.0.0.1:8101
//                                                               tcp://127.0.0.1:8103 3
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "ubii/ubii.hpp"

using namespace std::chrono_literals;

namespace
{

// Seconds since the Unix epoch (0 without a timestamp).
double seconds_of(const std::optional<ubii::Timestamp> &stamp)
{
    if (!stamp)
        return 0;
    if (stamp->seconds != 0 || stamp->nanos != 0)
        return static_cast<double>(stamp->seconds) + static_cast<double>(stamp->nanos) * 1e-9;
    return static_cast<double>(stamp->millis) / 1e3;
}

// Speed of a moving point, from consecutive positions and the time between passes.
class Speed : public ubii::ProcessingModule
{
  public:
    Speed()
        : ProcessingModule({"speed",
                            "speed of a moving point in units per second",
                            {ubii::input<ubii::Vector3>("position")},
                            {ubii::output<double>("speed")},
                            ubii::TriggerOnInput{20ms}})
    {
    }

  protected:
    void on_processing(ubii::Pass &pass) override
    {
        const ubii::Record &record = *pass.record("position");
        const ubii::Vector3 &position = record.as<ubii::Vector3>();
        // The time between the positions' timestamps where the master forwards them (the npm
        // master drops them), else the time between passes.
        const double taken = seconds_of(record.timestamp());
        const double elapsed = taken > 0 && last_taken_ > 0
                                   ? taken - last_taken_
                                   : std::chrono::duration<double>(pass.delta_time()).count();
        if (last_ && elapsed > 0) {
            const double dx = position.x() - last_->x(), dy = position.y() - last_->y(),
                         dz = position.z() - last_->z();
            pass.set_output("speed", std::sqrt(dx * dx + dy * dy + dz * dz) / elapsed);
        }
        last_ = position;
        last_taken_ = taken;
    }

  private:
    std::optional<ubii::Vector3> last_;
    double last_taken_ = 0;
};

} // namespace

int main(int argc, char **argv)
try {
    ubii::NodeOptions options;
    options.service_url = argc > 1 ? argv[1] : "tcp://127.0.0.1:8101";
    options.topic_url = argc > 2 ? argv[2] : "tcp://127.0.0.1:8103";
    const double seconds = argc > 3 ? std::stod(argv[3]) : 3.0;

    options.name = "libubii-cpp-example-tracker";
    ubii::Node tracker(options);
    options.name = "libubii-cpp-example-processing";
    ubii::Node processing(options);
    tracker.connect(10s);
    processing.connect(10s);
    const std::string base = "/" + tracker.client_id() + "/hand";

    ubii::RunningModule speed = processing.run(
        std::make_unique<Speed>(),
        ubii::Wiring().input("position", base + "/position").output("speed", base + "/speed"));
    int speeds = 0;
    double speed_sum = 0;
    auto printer =
        processing.subscribe<double>(base + "/speed", [&](double value, const ubii::RecordInfo &) {
            if (speeds++ % 25 == 0)
                std::printf("speed %.3f units/s\n", value);
            speed_sum += value;
        });
    processing.run_for(300ms); // the subscriptions reach the master

    const auto start = std::chrono::steady_clock::now();
    auto next = start;
    while (std::chrono::steady_clock::now() - start < std::chrono::duration<double>(seconds)) {
        const double t = std::chrono::duration<double>(next - start).count();
        tracker.publish(base + "/position", ubii::vector3(0.5 * std::cos(2 * M_PI * t / 1.0),
                                                          0.5 * std::sin(2 * M_PI * t / 1.0), 0));
        next += 10ms;
        while (std::chrono::steady_clock::now() < next) {
            tracker.poll(0ms);
            processing.poll(1ms); // waits no longer than the module's next pass is due
        }
    }
    processing.run_for(200ms);

    const ubii::Timing timing = speed.timing();
    std::printf("speed: %llu passes, interval mean %.1f ms (std %.1f ms, PM_perf %.2f), execution "
                "mean %.1f us, %llu inputs replaced unread, %llu errors\n",
                static_cast<unsigned long long>(timing.passes), timing.intervals.mean.count() * 1e3,
                timing.intervals.stddev.count() * 1e3, timing.interval_performance.value_or(0),
                timing.execution.mean.count() * 1e6,
                static_cast<unsigned long long>(timing.inputs_dropped),
                static_cast<unsigned long long>(timing.errors));
    if (speeds == 0) {
        std::fprintf(stderr, "processing_module_cpp: no speed arrived\n");
        return 1;
    }
    std::printf("%d speeds received, mean %.2f units/s (the circle's: %.2f)\n", speeds,
                speed_sum / speeds, 2 * M_PI * 0.5);
    return 0;
} catch (const std::exception &error) {
    std::fprintf(stderr, "processing_module_cpp: %s\n", error.what());
    return 1;
}
