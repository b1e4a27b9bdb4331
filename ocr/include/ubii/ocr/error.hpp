#ifndef UBII_OCR_ERROR_HPP
#define UBII_OCR_ERROR_HPP

// Every failure of the OCR layer is an exception derived from ubii::ocr::Error. The C core below
// never sees them: this layer sits above the C ABI.

#include <stdexcept>
#include <string>

namespace ubii::ocr
{

class Error : public std::runtime_error
{
  public:
    explicit Error(const std::string &message) : std::runtime_error(message)
    {
    }
};

// The image handed in cannot be used: empty, a byte count that does not match
// width x height x channels, an unknown data format, an unsupported pixel type.
class InvalidImage : public Error
{
  public:
    using Error::Error;
};

// The EAST model file is missing, unreadable, or not a network OpenCV's DNN module can load.
class ModelError : public Error
{
  public:
    using Error::Error;
};

// Tesseract could not start (language data missing) or refused a setting.
class EngineError : public Error
{
  public:
    using Error::Error;
};

// A pipeline name, option value or encoded record that makes no sense.
class InvalidArgument : public Error
{
  public:
    using Error::Error;
};

} // namespace ubii::ocr

#endif
