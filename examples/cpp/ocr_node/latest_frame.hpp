#ifndef UBII_EXAMPLE_OCR_NODE_LATEST_FRAME_HPP
#define UBII_EXAMPLE_OCR_NODE_LATEST_FRAME_HPP

// The newest image received, and nothing older. Recognising a frame takes longer than frames
// arrive, so the subscription callback keeps only the latest one (counting the ones it replaces as
// dropped) and the main loop takes it between polls: no queue can grow without bound, and no
// recognition runs inside a callback.

#include <cstdint>
#include <vector>

#include "ubii/node.hpp"
#include "ubii/ubii.h"

namespace ocr_node
{

// A copy of one received Image2D, or why the record could not be read as one.
struct Frame {
    ubii_status status = UBII_OK; // of ubii_record_image: not OK for a record that is no Image2D
    bool out_of_memory = false;   // the copy could not be made
    std::int32_t width = 0;
    std::int32_t height = 0;
    ubii_dataStructure_Image2D_DataFormat format = ubii_dataStructure_Image2D_DataFormat_GRAY8;
    std::vector<std::uint8_t> data;
    bool has_data = false; // the record carried a data field (possibly empty)

    // Borrows `data`, for ubii::ocr::image_to_mat.
    ubii_image_view view() const;
};

class LatestFrame
{
  public:
    // The subscription's handler: only copies the record's image (read without a copy of the
    // message); never throws.
    void on_record(const ubii::Record &record) noexcept;

    // Swaps the newest frame into `frame` (whose buffer is reused for the next one); false when
    // nothing arrived since the last take.
    bool take(Frame &frame) noexcept;

    std::uint64_t received() const
    {
        return received_;
    }
    std::uint64_t dropped() const
    {
        return dropped_;
    }

  private:
    Frame pending_;
    bool full_ = false;
    std::uint64_t received_ = 0;
    std::uint64_t dropped_ = 0;
};

} // namespace ocr_node

#endif
