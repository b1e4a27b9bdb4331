// The client framing both ports use (ports/common/websocket_frame.h), against RFC 6455 §5.2 and a
// byte-at-a-time reference of the masking.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

extern "C" {
#include "websocket_frame.h"
}

namespace
{

std::vector<uint8_t> payload_of(size_t size)
{
    std::vector<uint8_t> bytes(size);
    for (size_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<uint8_t>(i * 37 + 11);
    }
    return bytes;
}

TEST(WebSocketFrame, MaskingMatchesTheByteAtATimeDefinitionAtEveryLengthAndOffset)
{
    const uint8_t mask[4] = {0xA1, 0x02, 0xF3, 0x7C};
    for (size_t size = 0; size <= 70; ++size) {
        for (size_t offset = 0; offset < 8; ++offset) { // unaligned starts take the same path
            std::vector<uint8_t> buffer(offset + size);
            std::vector<uint8_t> original = payload_of(size);
            std::copy(original.begin(), original.end(), buffer.begin() + static_cast<long>(offset));
            ubii__ws_mask(buffer.data() + offset, size, mask);
            for (size_t i = 0; i < size; ++i) {
                ASSERT_EQ(buffer[offset + i], original[i] ^ mask[i % 4]) << size << "@" << i;
            }
        }
    }
}

TEST(WebSocketFrame, HeaderCarriesFinOpcodeMaskBitLengthAndKey)
{
    const uint8_t mask[4] = {1, 2, 3, 4};
    struct Case {
        size_t size;
        std::vector<uint8_t> length_bytes;
    };
    const Case cases[] = {
        {0, {0x80}},
        {125, {0x80 | 125}},
        {126, {0x80 | 126, 0x00, 0x7E}},
        {65535, {0x80 | 126, 0xFF, 0xFF}},
        {65536, {0x80 | 127, 0, 0, 0, 0, 0, 1, 0, 0}},
    };
    for (const Case &c : cases) {
        size_t header_size = ubii__ws_client_header_size(c.size);
        ASSERT_EQ(header_size, 1 + c.length_bytes.size() + 4) << c.size;
        ASSERT_LE(header_size, static_cast<size_t>(UBII_WS_MAX_CLIENT_HEADER));
        std::vector<uint8_t> header(header_size + 1, 0xEE);
        ubii__ws_write_client_header(header.data(), UBII_WS_OPCODE_BINARY, c.size, mask);
        EXPECT_EQ(header[0], 0x82) << "FIN and the binary opcode";
        for (size_t i = 0; i < c.length_bytes.size(); ++i) {
            EXPECT_EQ(header[1 + i], c.length_bytes[i]) << c.size << " length byte " << i;
        }
        for (size_t i = 0; i < 4; ++i) {
            EXPECT_EQ(header[1 + c.length_bytes.size() + i], mask[i]);
        }
        EXPECT_EQ(header[header_size], 0xEE) << "nothing written past the header";
    }
    uint8_t text[6];
    ubii__ws_write_client_header(text, UBII_WS_OPCODE_TEXT, 4, mask);
    EXPECT_EQ(text[0], 0x81);
}

} // namespace
