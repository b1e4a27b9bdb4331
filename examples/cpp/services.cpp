// services, in C++: what the master offers: its services, its topics and its clients
// (examples/c/services.c is its C twin).
//
//   services_cpp [SERVICE_URL [TOPIC_URL]]   defaults: tcp://127.0.0.1:8101 tcp://127.0.0.1:8103
#include <chrono>
#include <cstdio>

#include "ubii/ubii.hpp"

using namespace std::chrono_literals;

int main(int argc, char **argv)
try {
    ubii::NodeOptions options;
    options.service_url = argc > 1 ? argv[1] : "tcp://127.0.0.1:8101";
    options.topic_url = argc > 2 ? argv[2] : "tcp://127.0.0.1:8103";
    options.name = "libubii-cpp-example-services";
    ubii::Node node(options);
    node.connect(10s);

    std::printf("services:\n");
    const ubii::ServiceList services = node.wait(node.master().services(), 5s);
    bool has_client_list = false;
    for (const auto &service : services.elements()) {
        std::printf("  %-55s %s -> %s\n", service.topic().c_str(),
                    service.request_message_format().c_str(),
                    service.response_message_format().c_str());
        has_client_list = has_client_list || service.topic() == ubii::service_topics::client_list;
    }

    std::printf("topics (services first, then topics holding data):\n");
    const ubii::StringList topics = node.wait(node.master().topics(), 5s);
    for (const auto &topic : topics.elements())
        std::printf("  %s\n", topic.c_str());

    // The npm 0.4.0 master registers no /services/client/get_list (the current master does):
    // asking would only earn an error reply, so say what is missing instead.
    if (!has_client_list) {
        std::printf("clients: this master has no client list service (%s)\n",
                    ubii::service_topics::client_list);
        return 0;
    }
    const ubii::ClientList clients = node.wait(node.master().clients(), 5s);
    std::printf("clients:\n");
    for (const auto &client : clients.elements())
        std::printf("  %s  %s%s\n", client.id().c_str(), client.name().c_str(),
                    client.id() == node.client_id() ? "  (this node)" : "");
    return 0;
} catch (const std::exception &error) {
    std::fprintf(stderr, "services_cpp: %s\n", error.what());
    return 1;
}
