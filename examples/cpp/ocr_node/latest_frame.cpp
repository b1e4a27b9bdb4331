#include "latest_frame.hpp"

#include <new>
#include <utility>

namespace ocr_node
{

ubii_image_view Frame::view() const
{
    return ubii_image_view{width, height, format, has_data ? data.data() : nullptr, data.size()};
}

void LatestFrame::on_record(const ubii::Record &record) noexcept
{
    ++received_;
    if (full_)
        ++dropped_; // replaced before the main loop took it
    full_ = true;

    ubii::ImageView image;
    try {
        image = record.image();
        pending_.status = UBII_OK;
    } catch (const ubii::Error &error) { // not an Image2D, or not valid protobuf
        pending_.status = static_cast<ubii_status>(error.status());
    }
    pending_.out_of_memory = false;
    pending_.width = image.width;
    pending_.height = image.height;
    pending_.format = static_cast<ubii_dataStructure_Image2D_DataFormat>(image.format);
    pending_.has_data = pending_.status == UBII_OK && image.data != nullptr;
    try {
        // assign() keeps the buffer's capacity: frames of one size allocate once.
        if (pending_.has_data)
            pending_.data.assign(image.data, image.data + image.size);
        else
            pending_.data.clear();
    } catch (const std::bad_alloc &) {
        pending_.data.clear();
        pending_.has_data = false;
        pending_.out_of_memory = true;
    }
}

bool LatestFrame::take(Frame &frame) noexcept
{
    if (!full_)
        return false;
    std::swap(frame, pending_);
    full_ = false;
    return true;
}

} // namespace ocr_node
