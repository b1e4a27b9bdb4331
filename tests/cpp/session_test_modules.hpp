#ifndef UBII_TEST_SESSION_TEST_MODULES_HPP
#define UBII_TEST_SESSION_TEST_MODULES_HPP

// Processing modules and mapping helpers shared by the session tests on the scripted master
// (unit/session_host_test.cpp) and on the current master (integration/session_test.cpp).

#include <atomic>
#include <stdexcept>
#include <string>
#include <utility>

#include "ubii/ubii.hpp"

namespace ubii_session_test
{

// y = factor * x + offset on every x; counts its on_created when given a counter.
class Affine : public ubii::ProcessingModule
{
  public:
    Affine(std::string name, double factor, double offset, std::atomic<int> *created = nullptr)
        : ProcessingModule({std::move(name),
                            "y = factor * x + offset",
                            {ubii::input<double>("x")},
                            {ubii::output<double>("y")},
                            ubii::TriggerOnInput{}}),
          factor_(factor), offset_(offset), created_(created)
    {
    }
    void on_created() override
    {
        if (created_ != nullptr)
            ++*created_;
    }
    void on_processing(ubii::Pass &pass) override
    {
        pass.set_output("y", factor_ * pass.input<double>("x") + offset_);
    }

  private:
    double factor_, offset_;
    std::atomic<int> *created_;
};

// Its on_created throws (counted when given a counter).
class Broken : public ubii::ProcessingModule
{
  public:
    explicit Broken(std::string name, std::atomic<int> *tries = nullptr)
        : ProcessingModule({std::move(name), "", {}, {ubii::output<double>("y")}, ubii::Free{}}),
          tries_(tries)
    {
    }
    void on_created() override
    {
        if (tries_ != nullptr)
            ++*tries_;
        throw std::runtime_error("no camera attached");
    }
    void on_processing(ubii::Pass &) override
    {
    }

  private:
    std::atomic<int> *tries_;
};

// Sums the latest value of every muxed topic, and publishes each one again, demultiplexed by
// the identity the mux gave it.
class Gather : public ubii::ProcessingModule
{
  public:
    explicit Gather(std::string name)
        : ProcessingModule({std::move(name),
                            "",
                            {ubii::input<double>("values")},
                            {ubii::output<double>("sum"), ubii::output<double>("each")},
                            ubii::TriggerOnInput{}})
    {
    }
    void on_processing(ubii::Pass &pass) override
    {
        double sum = 0;
        for (const ubii::MuxedRecord &muxed : pass.muxed("values")) {
            sum += muxed.record->as<double>();
            pass.add_demuxed_output("each", muxed.record->as<double>(), {muxed.identity});
        }
        pass.set_output("sum", sum);
    }
};

inline void map_input(ubii::IOMapping &mapping, const std::string &input, const std::string &topic)
{
    auto &entry = *mapping.add_input_mappings();
    entry.set_input_name(input);
    entry.set_topic(topic);
}

inline void map_output(ubii::IOMapping &mapping, const std::string &output,
                       const std::string &topic)
{
    auto &entry = *mapping.add_output_mappings();
    entry.set_output_name(output);
    entry.set_topic(topic);
}

// A mux input over `selector` for members `data_type`, identity from `identity`.
inline void map_mux_input(ubii::IOMapping &mapping, const std::string &input,
                          const std::string &selector, const std::string &data_type,
                          const std::string &identity)
{
    auto &mux = *mapping.add_input_mappings();
    mux.set_input_name(input);
    mux.mutable_topic_mux()->set_topic_selector(selector);
    mux.mutable_topic_mux()->set_data_type(data_type);
    mux.mutable_topic_mux()->set_identity_match_pattern(identity);
}

// A demux output onto `format`'s topics for members `data_type`.
inline void map_demux_output(ubii::IOMapping &mapping, const std::string &output,
                             const std::string &format, const std::string &data_type)
{
    auto &demux = *mapping.add_output_mappings();
    demux.set_output_name(output);
    demux.mutable_topic_demux()->set_output_topic_format(format);
    demux.mutable_topic_demux()->set_data_type(data_type);
}

} // namespace ubii_session_test

#endif
