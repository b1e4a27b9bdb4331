#ifndef UBII_OCR_SRC_TESSERACT_MESSAGES_HPP
#define UBII_OCR_SRC_TESSERACT_MESSAGES_HPP

#include <string>

namespace ubii::ocr::detail
{

// The file Tesseract's debug_file variable names so that its messages land in the buffer
// take_tesseract_messages() reads: an anonymous in-memory file (memfd) of the process, made on
// the first call; "" if it cannot be made.
const std::string &tesseract_message_file();

} // namespace ubii::ocr::detail

#endif
