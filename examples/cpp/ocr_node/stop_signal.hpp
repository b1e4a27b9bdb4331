#ifndef UBII_EXAMPLE_OCR_NODE_STOP_SIGNAL_HPP
#define UBII_EXAMPLE_OCR_NODE_STOP_SIGNAL_HPP

// SIGINT and SIGTERM ask the main loop to stop; the handler only records the signal.

namespace ocr_node
{

// Installs the handlers (without SA_RESTART, so a signal also ends the poll it interrupts).
void catch_stop_signals();
// The signal received, 0 if none.
int stop_requested();

} // namespace ocr_node

#endif
