#ifndef UBII_NANOPB_PREFIX_H
#define UBII_NANOPB_PREFIX_H

/* libubii carries its own nanopb runtime (built without heap support). So that it can be linked
 * into a program that has another nanopb, every runtime function gets the prefix ubii_pb_. The
 * nanopb headers installed with libubii include this file first, so application code keeps
 * writing pb_decode(...) and reaches libubii's copy. */
#define pb_close_string_substream ubii_pb_close_string_substream
#define pb_decode ubii_pb_decode
#define pb_decode_bool ubii_pb_decode_bool
#define pb_decode_ex ubii_pb_decode_ex
#define pb_decode_fixed32 ubii_pb_decode_fixed32
#define pb_decode_fixed64 ubii_pb_decode_fixed64
#define pb_decode_svarint ubii_pb_decode_svarint
#define pb_decode_tag ubii_pb_decode_tag
#define pb_decode_varint ubii_pb_decode_varint
#define pb_decode_varint32 ubii_pb_decode_varint32
#define pb_default_field_callback ubii_pb_default_field_callback
#define pb_encode ubii_pb_encode
#define pb_encode_ex ubii_pb_encode_ex
#define pb_encode_fixed32 ubii_pb_encode_fixed32
#define pb_encode_fixed64 ubii_pb_encode_fixed64
#define pb_encode_string ubii_pb_encode_string
#define pb_encode_submessage ubii_pb_encode_submessage
#define pb_encode_svarint ubii_pb_encode_svarint
#define pb_encode_tag ubii_pb_encode_tag
#define pb_encode_tag_for_field ubii_pb_encode_tag_for_field
#define pb_encode_varint ubii_pb_encode_varint
#define pb_field_iter_begin ubii_pb_field_iter_begin
#define pb_field_iter_begin_const ubii_pb_field_iter_begin_const
#define pb_field_iter_begin_extension ubii_pb_field_iter_begin_extension
#define pb_field_iter_begin_extension_const ubii_pb_field_iter_begin_extension_const
#define pb_field_iter_find ubii_pb_field_iter_find
#define pb_field_iter_find_extension ubii_pb_field_iter_find_extension
#define pb_field_iter_next ubii_pb_field_iter_next
#define pb_get_encoded_size ubii_pb_get_encoded_size
#define pb_istream_from_buffer ubii_pb_istream_from_buffer
#define pb_make_string_substream ubii_pb_make_string_substream
#define pb_ostream_from_buffer ubii_pb_ostream_from_buffer
#define pb_read ubii_pb_read
#define pb_release ubii_pb_release
#define pb_skip_field ubii_pb_skip_field
#define pb_write ubii_pb_write

#endif
