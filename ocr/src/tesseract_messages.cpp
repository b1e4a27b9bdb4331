#include "tesseract_messages.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <mutex>

#include "ubii/ocr/tesseract_messages.hpp"

namespace ubii::ocr
{
namespace
{

// Tesseract's message file is one per process (tprintf keeps a static FILE*), so its reader is
// too. Tesseract writes through a FILE of its own, at its own offset; this reads behind it with
// pread, never moving that offset.
class MessageFile
{
  public:
    MessageFile() : fd_(memfd_create("ubii-tesseract-messages", MFD_CLOEXEC))
    {
        if (fd_ >= 0)
            path_ = "/proc/self/fd/" + std::to_string(fd_);
    }
    ~MessageFile()
    {
        if (fd_ >= 0)
            ::close(fd_);
    }
    MessageFile(const MessageFile &) = delete;
    MessageFile &operator=(const MessageFile &) = delete;

    const std::string &path() const noexcept
    {
        return path_;
    }

    std::vector<std::string> take()
    {
        std::vector<std::string> lines;
        if (fd_ < 0)
            return lines;
        // Tesseract's FILE is fully buffered and never flushed by it.
        std::fflush(nullptr);
        const std::lock_guard<std::mutex> lock(mutex_);
        char buffer[4096];
        for (;;) {
            const ssize_t count = ::pread(fd_, buffer, sizeof buffer, read_);
            if (count <= 0)
                break;
            read_ += count;
            partial_.append(buffer, static_cast<std::size_t>(count));
        }
        std::size_t start = 0;
        for (std::size_t end; (end = partial_.find('\n', start)) != std::string::npos;
             start = end + 1) {
            if (end > start)
                lines.push_back(partial_.substr(start, end - start));
        }
        partial_.erase(0, start);
        return lines;
    }

  private:
    int fd_;
    std::string path_;
    std::mutex mutex_;
    off_t read_ = 0;
    std::string partial_;
};

MessageFile &message_file()
{
    static MessageFile file;
    return file;
}

} // namespace

namespace detail
{
const std::string &tesseract_message_file()
{
    return message_file().path();
}
} // namespace detail

std::vector<std::string> take_tesseract_messages()
{
    return message_file().take();
}

} // namespace ubii::ocr
