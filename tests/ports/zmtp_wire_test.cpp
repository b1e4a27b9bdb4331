// ZMTP framing (ports/common/zmtp_wire.c) on hand-written bytes: what a broken stream looks like
// must end the connection, not have the receiver skip what it believes is a large message.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

extern "C" {
#include "zmtp_wire.h"
}

namespace
{

ubii_zmtp_unit next(const std::vector<uint8_t> &bytes, uint64_t max_message, ubii_zmtp_found &found)
{
    ubii_zmtp_step step = UBII_ZMTP_STEP_OPEN;
    return ubii__zmtp_next(&step, bytes.data(), bytes.size(), max_message, &found);
}

TEST(ZmtpWire, AMessageOfTheMastersShapeIsFound)
{
    const std::vector<uint8_t> bytes = {0x01, 0x00, 0x00, 0x04, 'P', 'I', 'N', 'G'};
    ubii_zmtp_found found;
    ASSERT_EQ(next(bytes, 2048, found), UBII_ZMTP_MESSAGE);
    EXPECT_EQ(found.consumed, bytes.size());
    EXPECT_EQ(found.size, 4u);
}

TEST(ZmtpWire, AFrameOverTheReceiversLimitIsTooLargeToKeep)
{
    // A LONG frame of 4096 bytes: legitimate, but over this receiver's 2048 (it may skip it).
    const std::vector<uint8_t> bytes = {0x02, 0, 0, 0, 0, 0, 0, 0x10, 0x00};
    ubii_zmtp_found found;
    EXPECT_EQ(next(bytes, 2048, found), UBII_ZMTP_TOO_LARGE);
}

TEST(ZmtpWire, ReservedFlagBitsAreACorruptStream)
{
    // The master's message with every byte inverted (as a corrupting link would deliver it).
    std::vector<uint8_t> bytes = {0x01, 0x00, 0x00, 0x04, 'P', 'I', 'N', 'G'};
    for (auto &byte : bytes)
        byte = static_cast<uint8_t>(~byte);
    ubii_zmtp_found found;
    ASSERT_EQ(next(bytes, 2048, found), UBII_ZMTP_ERROR);
    ASSERT_NE(found.error, nullptr);
}

TEST(ZmtpWire, ACommandWithMoreIsACorruptStream)
{
    const std::vector<uint8_t> bytes = {0x05, 0x00};
    ubii_zmtp_found found;
    EXPECT_EQ(next(bytes, 2048, found), UBII_ZMTP_ERROR);
}

TEST(ZmtpWire, ASizeBeyondAnyMessageIsACorruptStream)
{
    // 2^40 bytes: no master sends that; skipping it would swallow the rest of the connection.
    const std::vector<uint8_t> bytes = {0x02, 0, 0, 0, 0x01, 0, 0, 0, 0};
    ubii_zmtp_found found;
    EXPECT_EQ(next(bytes, 2048, found), UBII_ZMTP_ERROR);
}

} // namespace
