#include "stop_signal.hpp"

#include <csignal>

#include <signal.h>

namespace ocr_node
{
namespace
{

volatile std::sig_atomic_t received_signal = 0;

extern "C" void on_stop_signal(int signal_number)
{
    received_signal = signal_number;
}

} // namespace

void catch_stop_signals()
{
    struct sigaction action = {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int stop_requested()
{
    return received_signal;
}

} // namespace ocr_node
