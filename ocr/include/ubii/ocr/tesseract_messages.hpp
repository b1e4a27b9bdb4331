#ifndef UBII_OCR_TESSERACT_MESSAGES_HPP
#define UBII_OCR_TESSERACT_MESSAGES_HPP

// Tesseract prints warnings and debugging statistics ("Empty page!!", "Line cannot be
// recognized!!", tables of numbers for a blank single-line image) through its own printf, for the
// whole process, to stderr. The first pipeline a process makes redirects them into a buffer in
// memory instead (Tesseract's debug_file, a process-wide setting), and take_tesseract_messages()
// empties it: a node logs them (the OCR modules hand them to Pass::log) rather than letting them
// interleave with its output.

#include <string>
#include <vector>

namespace ubii::ocr
{

// The lines Tesseract printed since the previous call, in order (any engine in the process; with
// several pipelines on several threads a line may come back to another caller than the one whose
// frame caused it). Empty when nothing was printed or the redirection could not be set up (then
// Tesseract prints to stderr as before).
std::vector<std::string> take_tesseract_messages();

} // namespace ubii::ocr

#endif
