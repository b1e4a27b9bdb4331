#include "pb_test_callbacks.h"

#include <stdexcept>

namespace ubii_test
{
namespace
{

bool decode_string(pb_istream_t *stream, const pb_field_t *, void **arg)
{
    auto *storage = static_cast<StringValues *>(*arg);
    std::string value(stream->bytes_left, '\0');
    if (!pb_read(stream, reinterpret_cast<pb_byte_t *>(value.data()), value.size())) {
        return false;
    }
    storage->values.push_back(std::move(value));
    return true;
}

bool encode_strings(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    const auto *storage = static_cast<const StringValues *>(*arg);
    for (const std::string &value : storage->values) {
        if (!pb_encode_tag_for_field(stream, field) ||
            !pb_encode_string(stream, reinterpret_cast<const pb_byte_t *>(value.data()),
                              value.size())) {
            return false;
        }
    }
    return true;
}

// nanopb hands a packed array to the callback as one substream and calls again while bytes remain.
bool decode_fixed32(pb_istream_t *stream, const pb_field_t *, void **arg)
{
    auto *storage = static_cast<Fixed32Values *>(*arg);
    uint32_t value;
    if (!pb_decode_fixed32(stream, &value)) {
        return false;
    }
    storage->values.push_back(value);
    return true;
}

bool encode_packed_fixed32(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    const auto *storage = static_cast<const Fixed32Values *>(*arg);
    if (storage->values.empty()) {
        return true;
    }
    if (!pb_encode_tag(stream, PB_WT_STRING, field->tag) ||
        !pb_encode_varint(stream, storage->values.size() * 4)) {
        return false;
    }
    for (uint32_t value : storage->values) {
        if (!pb_encode_fixed32(stream, &value)) {
            return false;
        }
    }
    return true;
}

} // namespace

void decode_into(pb_callback_t &callback, StringValues &storage)
{
    callback.funcs.decode = decode_string;
    callback.arg = &storage;
}

void encode_from(pb_callback_t &callback, const StringValues &storage)
{
    callback.funcs.encode = encode_strings;
    callback.arg = const_cast<StringValues *>(&storage);
}

void decode_into(pb_callback_t &callback, Fixed32Values &storage)
{
    callback.funcs.decode = decode_fixed32;
    callback.arg = &storage;
}

void encode_packed_from(pb_callback_t &callback, const Fixed32Values &storage)
{
    callback.funcs.encode = encode_packed_fixed32;
    callback.arg = const_cast<Fixed32Values *>(&storage);
}

std::vector<uint8_t> from_hex(const std::string &hex)
{
    if (hex.size() % 2 != 0) {
        throw std::invalid_argument("odd number of hex digits");
    }
    std::vector<uint8_t> bytes;
    for (size_t i = 0; i < hex.size(); i += 2) {
        bytes.push_back(static_cast<uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
    }
    return bytes;
}

std::string to_hex(const uint8_t *bytes, size_t size)
{
    static const char digits[] = "0123456789abcdef";
    std::string hex;
    for (size_t i = 0; i < size; ++i) {
        hex += digits[bytes[i] >> 4];
        hex += digits[bytes[i] & 0xf];
    }
    return hex;
}

} // namespace ubii_test
