// A C++ application built against an installed libubii's C++ layer: records and values work, and a
// node given a master that is not there says so with ubii::Timeout within the time it was given.
#include <chrono>
#include <cstdio>

#include "ubii/ubii.hpp"

int main()
{
    ubii::Record record("/consumer/hand", ubii::vector3(1, 2, 3));
    const ubii::Record kept = record;
    if (kept.type() != ubii::RecordType::VECTOR3 || kept.as<ubii::Vector3>().y() != 2.0) {
        std::fprintf(stderr, "consumer_cpp: the record did not keep its value\n");
        return 1;
    }
    ubii::NodeOptions options;
    options.service_url = "tcp://127.0.0.1:9"; // nothing listens there
    ubii::Node node(options);
    const auto start = std::chrono::steady_clock::now();
    try {
        node.connect(std::chrono::milliseconds(300));
        std::fprintf(stderr, "consumer_cpp: connected to nothing\n");
        return 1;
    } catch (const ubii::Timeout &) {
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(3)) {
        std::fprintf(stderr, "consumer_cpp: connect() overran its timeout\n");
        return 1;
    }
    std::printf("consumer_cpp: %s member %s, connect timed out as asked\n",
                std::string(ubii::message_format(kept.type())).c_str(),
                std::string(ubii::record_type_name(kept.type())).c_str());
    return 0;
}
