/* Test tool for the protobufjs round trip (protobufjs_roundtrip.js). Works on any message of the
 * schema through nanopb's field descriptors alone.
 *
 *   codec_tool reencode TYPE      frames in on stdin, frames out on stdout: each message decoded
 *                                 into our generated struct and encoded again
 *   codec_tool generate TYPE SEED COUNT
 *                                 COUNT pseudo-random messages encoded by us: frames on stdout, and
 *                                 for each a line of canonical JSON on stderr
 *
 * TYPE is TopicData, ServiceRequest or ServiceReply; a frame is a 4-byte little-endian length and
 * the message. Canonical JSON lists what is on the wire, keyed by field number: floats as their bit
 * pattern (uint32 number), doubles as 16 hex digits, int64 as a decimal string, bytes as hex.
 *
 * Callback fields (free text, bytes, repeated fields) are not decoded into the struct; reencode
 * carries their bytes through as the core will hand them on (scalars always re-emitted packed).
 * Test code: it allocates freely and exits on any failure. */
#include <inttypes.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <pb_common.h>
#include <pb_decode.h>
#include <pb_encode.h>

#include "ubii/services/serviceReply.pb.h"
#include "ubii/services/serviceRequest.pb.h"
#include "ubii/topicData/topicData.pb.h"

enum { SCRATCH_BYTES = 1 << 16, MAX_MESSAGE = 1 << 20, MAX_SLOTS = 4096 };

static void fail(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fputs("codec_tool: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    exit(1);
}

/* ---- callback slots: the raw occurrences of one callback field --------------------------------
 */

typedef struct occurrence {
    uint8_t *bytes;
    size_t size;
} occurrence;

typedef struct slot {
    pb_callback_t *callback;
    int is_oneof_hook;
    occurrence *items;
    size_t count;
} slot;

typedef struct registry {
    slot *slots[MAX_SLOTS];
    size_t count;
} registry;

static slot *add_slot(registry *reg, pb_callback_t *callback, int is_oneof_hook)
{
    if (reg->count == MAX_SLOTS) {
        fail("too many callback fields");
    }
    slot *s = calloc(1, sizeof *s);
    s->callback = callback;
    s->is_oneof_hook = is_oneof_hook;
    reg->slots[reg->count++] = s;
    return s;
}

static void add_occurrence(slot *s, const uint8_t *bytes, size_t size)
{
    s->items = realloc(s->items, (s->count + 1) * sizeof *s->items);
    s->items[s->count].bytes = malloc(size ? size : 1);
    memcpy(s->items[s->count].bytes, bytes, size);
    s->items[s->count].size = size;
    s->count++;
}

static int is_length_delimited(pb_type_t type)
{
    pb_type_t ltype = PB_LTYPE(type);
    return ltype == PB_LTYPE_STRING || ltype == PB_LTYPE_BYTES || PB_LTYPE_IS_SUBMSG(type);
}

static bool capture(pb_istream_t *stream, const pb_field_t *field, void **arg)
{
    (void)field;
    uint8_t buffer[MAX_MESSAGE / 16];
    size_t size = stream->bytes_left;
    if (size > sizeof buffer || !pb_read(stream, buffer, size)) {
        return false;
    }
    add_occurrence(*arg, buffer, size);
    return true;
}

/* Strings, bytes and messages go out one occurrence each; scalars as one packed field. */
static bool emit(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    const slot *s = *arg;
    if (is_length_delimited(field->type)) {
        for (size_t i = 0; i < s->count; ++i) {
            if (!pb_encode_tag(stream, PB_WT_STRING, field->tag) ||
                !pb_encode_string(stream, s->items[i].bytes, s->items[i].size)) {
                return false;
            }
        }
        return true;
    }
    size_t total = 0;
    for (size_t i = 0; i < s->count; ++i) {
        total += s->items[i].size;
    }
    if (total == 0) {
        return true;
    }
    if (!pb_encode_tag(stream, PB_WT_STRING, field->tag) || !pb_encode_varint(stream, total)) {
        return false;
    }
    for (size_t i = 0; i < s->count; ++i) {
        if (!pb_write(stream, s->items[i].bytes, s->items[i].size)) {
            return false;
        }
    }
    return true;
}

static void install_capture(registry *reg, const pb_msgdesc_t *desc, void *message);

static bool on_oneof_member(pb_istream_t *stream, const pb_field_t *field, void **arg)
{
    (void)stream;
    if (PB_LTYPE_IS_SUBMSG(field->type)) {
        install_capture(*arg, field->submsg_desc, field->pData);
    }
    return true;
}

/* Binds every callback field of `message` (and of its static submessages) to capture(). */
static void install_capture(registry *reg, const pb_msgdesc_t *desc, void *message)
{
    pb_field_iter_t iter;
    if (!pb_field_iter_begin(&iter, desc, message)) {
        return;
    }
    const void *hooked_oneof = NULL;
    do {
        if (PB_ATYPE(iter.type) == PB_ATYPE_CALLBACK) {
            pb_callback_t *callback = iter.pData;
            callback->funcs.decode = capture;
            callback->arg = add_slot(reg, callback, 0);
        } else if (PB_LTYPE(iter.type) == PB_LTYPE_SUBMSG_W_CB && iter.pSize != hooked_oneof) {
            pb_callback_t *hook = (pb_callback_t *)iter.pSize - 1;
            hook->funcs.decode = on_oneof_member;
            hook->arg = reg;
            add_slot(reg, hook, 1);
            hooked_oneof = iter.pSize;
        } else if (PB_LTYPE(iter.type) == PB_LTYPE_SUBMESSAGE &&
                   PB_HTYPE(iter.type) != PB_HTYPE_ONEOF) {
            install_capture(reg, iter.submsg_desc, iter.pData);
        }
    } while (pb_field_iter_next(&iter));
}

/* nanopb's callback holds a decoder or an encoder; before encoding, captured fields re-emit and
 * the oneof hooks (which nanopb also calls while encoding) are cleared. */
static void switch_to_encoding(registry *reg)
{
    for (size_t i = 0; i < reg->count; ++i) {
        slot *s = reg->slots[i];
        s->callback->funcs.encode = s->is_oneof_hook ? NULL : emit;
        if (!s->is_oneof_hook) {
            s->callback->arg = s;
        }
    }
}

static void free_registry(registry *reg)
{
    for (size_t i = 0; i < reg->count; ++i) {
        for (size_t j = 0; j < reg->slots[i]->count; ++j) {
            free(reg->slots[i]->items[j].bytes);
        }
        free(reg->slots[i]->items);
        free(reg->slots[i]);
    }
    reg->count = 0;
}

/* ---- framing ------------------------------------------------------------------------------------
 */

static int read_frame(uint8_t *buffer, size_t *size)
{
    uint8_t header[4];
    size_t got = fread(header, 1, 4, stdin);
    if (got == 0) {
        return 0;
    }
    if (got != 4) {
        fail("truncated frame header");
    }
    *size = (size_t)header[0] | (size_t)header[1] << 8 | (size_t)header[2] << 16 |
            (size_t)header[3] << 24;
    if (*size > MAX_MESSAGE || fread(buffer, 1, *size, stdin) != *size) {
        fail("truncated or oversized frame");
    }
    return 1;
}

static void write_frame(const uint8_t *bytes, size_t size)
{
    uint8_t header[4] = {(uint8_t)size, (uint8_t)(size >> 8), (uint8_t)(size >> 16),
                         (uint8_t)(size >> 24)};
    fwrite(header, 1, 4, stdout);
    fwrite(bytes, 1, size, stdout);
}

/* ---- reencode -----------------------------------------------------------------------------------
 */

static _Alignas(max_align_t) uint8_t scratch[SCRATCH_BYTES];
static uint8_t input[MAX_MESSAGE];
static uint8_t output[MAX_MESSAGE];

static void reencode(const pb_msgdesc_t *desc)
{
    size_t size;
    registry reg = {{0}, 0};
    while (read_frame(input, &size)) {
        memset(scratch, 0, sizeof scratch);
        install_capture(&reg, desc, scratch);
        pb_istream_t in = pb_istream_from_buffer(input, size);
        if (!pb_decode(&in, desc, scratch)) {
            fail("decode failed: %s", PB_GET_ERROR(&in));
        }
        switch_to_encoding(&reg);
        pb_ostream_t out = pb_ostream_from_buffer(output, sizeof output);
        if (!pb_encode(&out, desc, scratch)) {
            fail("encode failed: %s", PB_GET_ERROR(&out));
        }
        write_frame(output, out.bytes_written);
        free_registry(&reg);
    }
}

/* ---- generate -----------------------------------------------------------------------------------
 */

static uint64_t rng_state;

static uint64_t next_random(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return rng_state;
}

static uint64_t random_below(uint64_t limit)
{
    return next_random() % limit;
}

static size_t random_text(char *text, size_t capacity)
{
    static const char alphabet[] =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 /._-";
    size_t length = (size_t)random_below(capacity < 24 ? capacity : 24);
    for (size_t i = 0; i < length; ++i) {
        text[i] = alphabet[random_below(sizeof alphabet - 1)];
    }
    text[length] = '\0';
    return length;
}

/* Scalars are drawn so that zero appears often enough to exercise proto3's default rules. */
static void random_scalar(pb_field_iter_t *iter, void *data)
{
    pb_type_t ltype = PB_LTYPE(iter->type);
    int zero = random_below(6) == 0;
    if (ltype == PB_LTYPE_BOOL) {
        *(bool *)data = !zero && random_below(2);
    } else if (ltype == PB_LTYPE_FIXED32) { /* float */
        float value = zero ? 0.0f : (float)((double)(int64_t)next_random() / 1e12);
        memcpy(data, &value, sizeof value);
    } else if (ltype == PB_LTYPE_FIXED64) { /* double */
        double value = zero ? 0.0 : (double)(int64_t)next_random() / 1e9;
        memcpy(data, &value, sizeof value);
    } else if (iter->data_size == 8) {
        int64_t value = zero ? 0 : (int64_t)next_random() >> random_below(63);
        memcpy(data, &value, sizeof value);
    } else {
        int32_t value = zero ? 0 : (int32_t)(next_random() >> 33) - (1 << 29);
        memcpy(data, &value, sizeof value);
    }
}

static bool emit_generated(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    return emit(stream, field, arg);
}

static void generate_message(registry *reg, const pb_msgdesc_t *desc, void *message, int depth);

/* nanopb uses one htype for proto3 singular fields and fields with a has_ flag; only the latter
 * have pSize. */
static int has_presence_flag(const pb_field_iter_t *iter)
{
    return PB_HTYPE(iter->type) == PB_HTYPE_OPTIONAL && iter->pSize != NULL;
}

static void generate_field(registry *reg, pb_field_iter_t *iter, int depth)
{
    if (PB_ATYPE(iter->type) == PB_ATYPE_CALLBACK) {
        /* Text fields get content; repeated scalars and messages stay empty in this direction
         * (the reencode direction carries them). */
        pb_callback_t *callback = iter->pData;
        slot *s = add_slot(reg, callback, 0);
        callback->funcs.encode = emit_generated;
        callback->arg = s;
        pb_type_t ltype = PB_LTYPE(iter->type);
        if (ltype == PB_LTYPE_STRING || ltype == PB_LTYPE_BYTES) {
            size_t count = PB_HTYPE(iter->type) == PB_HTYPE_REPEATED ? random_below(4) : 1;
            for (size_t i = 0; i < count; ++i) {
                char text[32];
                size_t length = random_text(text, sizeof text);
                if (length > 0 || PB_HTYPE(iter->type) == PB_HTYPE_REPEATED) {
                    add_occurrence(s, (const uint8_t *)text, length);
                }
            }
        }
        return;
    }
    if (PB_LTYPE(iter->type) == PB_LTYPE_STRING) {
        random_text(iter->pData, iter->data_size);
    } else if (PB_LTYPE_IS_SUBMSG(iter->type)) {
        generate_message(reg, iter->submsg_desc, iter->pData, depth + 1);
    } else {
        random_scalar(iter, iter->pData);
    }
}

static void generate_message(registry *reg, const pb_msgdesc_t *desc, void *message, int depth)
{
    pb_field_iter_t iter;
    if (!pb_field_iter_begin(&iter, desc, message)) {
        return;
    }
    do {
        if (PB_LTYPE(iter.type) == PB_LTYPE_SUBMSG_W_CB) {
            pb_callback_t *hook = (pb_callback_t *)iter.pSize - 1;
            hook->funcs.encode = NULL;
        }
        pb_type_t htype = PB_HTYPE(iter.type);
        if (PB_ATYPE(iter.type) == PB_ATYPE_CALLBACK) {
            generate_field(reg, &iter, depth); /* callbacks have no presence flag of their own */
        } else if (htype == PB_HTYPE_ONEOF) {
            /* Choose the member once per oneof: count its members, pick one, fill it. */
            pb_size_t *which = iter.pSize;
            if (*which != 0 && *which != iter.tag) {
                continue;
            }
            if (*which == 0) {
                pb_field_iter_t member = iter;
                size_t members = 0;
                do {
                    members++;
                } while (pb_field_iter_next(&member) && member.pSize == iter.pSize);
                size_t pick = (size_t)random_below(members + 1);
                if (pick == members || depth > 6) {
                    *which = (pb_size_t)-1; /* leave the oneof empty */
                    continue;
                }
                member = iter;
                for (size_t i = 0; i < pick; ++i) {
                    pb_field_iter_next(&member);
                }
                *which = member.tag;
                if (member.tag != iter.tag) {
                    continue;
                }
            }
            generate_field(reg, &iter, depth);
        } else if (has_presence_flag(&iter)) {
            if (random_below(3) != 0 && depth <= 6) {
                *(bool *)iter.pSize = true;
                generate_field(reg, &iter, depth);
            }
        } else {
            generate_field(reg, &iter, depth);
        }
    } while (pb_field_iter_next(&iter));
    /* Undo the "left empty" marker. */
    if (pb_field_iter_begin(&iter, desc, message)) {
        do {
            if (PB_HTYPE(iter.type) == PB_HTYPE_ONEOF &&
                *(pb_size_t *)iter.pSize == (pb_size_t)-1) {
                *(pb_size_t *)iter.pSize = 0;
            }
        } while (pb_field_iter_next(&iter));
    }
}

/* ---- canonical JSON of what nanopb puts on the wire ---------------------------------------------
 */

static void print_hex(const uint8_t *bytes, size_t size)
{
    fputc('"', stderr);
    for (size_t i = 0; i < size; ++i) {
        fprintf(stderr, "%02x", bytes[i]);
    }
    fputc('"', stderr);
}

static void print_json_string(const char *text, size_t length)
{
    fputc('"', stderr);
    fwrite(text, 1, length, stderr); /* generated text needs no escaping */
    fputc('"', stderr);
}

static int all_zero(const void *data, size_t size)
{
    const uint8_t *bytes = data;
    for (size_t i = 0; i < size; ++i) {
        if (bytes[i] != 0) {
            return 0;
        }
    }
    return 1;
}

static void print_message(const pb_msgdesc_t *desc, void *message);

static void print_scalar(const pb_field_iter_t *iter, const void *data)
{
    pb_type_t ltype = PB_LTYPE(iter->type);
    if (ltype == PB_LTYPE_BOOL) {
        fputs(*(const bool *)data ? "true" : "false", stderr);
    } else if (ltype == PB_LTYPE_FIXED32) {
        uint32_t bits;
        memcpy(&bits, data, sizeof bits);
        fprintf(stderr, "%" PRIu32, bits);
    } else if (ltype == PB_LTYPE_FIXED64) {
        uint64_t bits;
        memcpy(&bits, data, sizeof bits);
        fprintf(stderr, "\"%016" PRIx64 "\"", bits);
    } else if (iter->data_size == 8) {
        int64_t value;
        memcpy(&value, data, sizeof value);
        fprintf(stderr, "\"%" PRId64 "\"", value);
    } else {
        int32_t value;
        memcpy(&value, data, sizeof value);
        fprintf(stderr, "%" PRId32, value);
    }
}

/* Prints "tag":value for a field nanopb will encode; returns whether it printed. */
static int print_field(const pb_field_iter_t *iter, int first)
{
    pb_type_t htype = PB_HTYPE(iter->type);
    pb_type_t ltype = PB_LTYPE(iter->type);
    if (PB_ATYPE(iter->type) == PB_ATYPE_CALLBACK) {
        const pb_callback_t *callback = iter->pData;
        const slot *s = callback->arg;
        if (s == NULL || s->count == 0) {
            return 0;
        }
        fprintf(stderr, "%s\"%u\":", first ? "" : ",", (unsigned)iter->tag);
        int repeated = htype == PB_HTYPE_REPEATED;
        if (repeated) {
            fputc('[', stderr);
        }
        for (size_t i = 0; i < s->count; ++i) {
            if (i > 0) {
                fputc(',', stderr);
            }
            if (ltype == PB_LTYPE_BYTES) {
                print_hex(s->items[i].bytes, s->items[i].size);
            } else {
                print_json_string((const char *)s->items[i].bytes, s->items[i].size);
            }
        }
        if (repeated) {
            fputc(']', stderr);
        }
        return 1;
    }
    if (htype == PB_HTYPE_ONEOF && *(const pb_size_t *)iter->pSize != iter->tag) {
        return 0;
    }
    if (has_presence_flag(iter) && !*(const bool *)iter->pSize) {
        return 0;
    }
    if (htype == PB_HTYPE_SINGULAR && !has_presence_flag(iter)) {
        if (ltype == PB_LTYPE_STRING ? ((const char *)iter->pData)[0] == '\0'
                                     : all_zero(iter->pData, iter->data_size)) {
            return 0;
        }
    }
    fprintf(stderr, "%s\"%u\":", first ? "" : ",", (unsigned)iter->tag);
    if (ltype == PB_LTYPE_STRING) {
        print_json_string(iter->pData, strlen(iter->pData));
    } else if (PB_LTYPE_IS_SUBMSG(iter->type)) {
        print_message(iter->submsg_desc, iter->pData);
    } else {
        print_scalar(iter, iter->pData);
    }
    return 1;
}

static void print_message(const pb_msgdesc_t *desc, void *message)
{
    pb_field_iter_t iter;
    int first = 1;
    fputc('{', stderr);
    if (pb_field_iter_begin(&iter, desc, message)) {
        do {
            if (print_field(&iter, first)) {
                first = 0;
            }
        } while (pb_field_iter_next(&iter));
    }
    fputc('}', stderr);
}

static void generate(const pb_msgdesc_t *desc, uint64_t seed, long count)
{
    rng_state = seed * 0x9E3779B97F4A7C15ull + 1;
    registry reg = {{0}, 0};
    for (long i = 0; i < count; ++i) {
        memset(scratch, 0, sizeof scratch);
        generate_message(&reg, desc, scratch, 0);
        pb_ostream_t out = pb_ostream_from_buffer(output, sizeof output);
        if (!pb_encode(&out, desc, scratch)) {
            fail("encode failed: %s", PB_GET_ERROR(&out));
        }
        write_frame(output, out.bytes_written);
        print_message(desc, scratch);
        fputc('\n', stderr);
        free_registry(&reg);
    }
}

int main(int argc, char **argv)
{
    static const struct {
        const char *name;
        const pb_msgdesc_t *desc;
    } types[] = {
        {"TopicData", ubii_topicData_TopicData_fields},
        {"ServiceRequest", ubii_services_ServiceRequest_fields},
        {"ServiceReply", ubii_services_ServiceReply_fields},
    };
    const pb_msgdesc_t *desc = NULL;
    for (size_t i = 0; argc > 2 && i < sizeof types / sizeof types[0]; ++i) {
        if (strcmp(argv[2], types[i].name) == 0) {
            desc = types[i].desc;
        }
    }
    if (desc == NULL) {
        fail("usage: codec_tool reencode|generate TopicData|ServiceRequest|ServiceReply [SEED "
             "COUNT]");
    }
    if (strcmp(argv[1], "reencode") == 0) {
        reencode(desc);
    } else if (strcmp(argv[1], "generate") == 0 && argc == 5) {
        generate(desc, strtoull(argv[3], NULL, 10), strtol(argv[4], NULL, 10));
    } else {
        fail("unknown mode %s", argv[1]);
    }
    return 0;
}
