#ifndef UBII_TEST_PB_CALLBACKS_H
#define UBII_TEST_PB_CALLBACKS_H

// nanopb callbacks that keep callback fields' contents in std::vectors, so tests can decode
// a message, look at it, and encode it again.

#include <cstdint>
#include <string>
#include <vector>

#include <pb_decode.h>
#include <pb_encode.h>

namespace ubii_test
{

// Every occurrence of a repeated string/bytes field, or the one value of a singular one.
struct StringValues {
    std::vector<std::string> values;
};

// The elements of a repeated fixed32 field (float), written packed.
struct Fixed32Values {
    std::vector<uint32_t> values;
};

// nanopb's callback holds either a decoder or an encoder, so a field is bound for one direction.
void decode_into(pb_callback_t &callback, StringValues &storage);
void encode_from(pb_callback_t &callback, const StringValues &storage);
void decode_into(pb_callback_t &callback, Fixed32Values &storage);
void encode_packed_from(pb_callback_t &callback, const Fixed32Values &storage);

std::vector<uint8_t> from_hex(const std::string &hex);
std::string to_hex(const uint8_t *bytes, size_t size);

} // namespace ubii_test

#endif
