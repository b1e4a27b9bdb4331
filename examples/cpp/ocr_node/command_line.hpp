#ifndef UBII_EXAMPLE_OCR_NODE_COMMAND_LINE_HPP
#define UBII_EXAMPLE_OCR_NODE_COMMAND_LINE_HPP

// ocr_node's command line: the pipeline, its main options, the master and the topics.

#include <stdexcept>
#include <string>

#include "ubii/ocr/pipeline_factory.hpp"

namespace ocr_node
{

struct Settings {
    ubii::ocr::PipelineOptions pipeline;
    std::string service_url = "tcp://127.0.0.1:8101";
    std::string topic_url = "tcp://127.0.0.1:8103";
    std::string input_topic = "/ocr/image";
    std::string output_topic = "/ocr/objects";
    double connect_timeout_s = 10.0;
    bool help = false;
};

// A command line that makes no sense; the message says what is wrong.
class UsageError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

// Throws UsageError (or ubii::ocr::InvalidArgument for an unknown pipeline name).
Settings parse_command_line(int argc, char **argv);

// The --help text.
std::string usage();

} // namespace ocr_node

#endif
