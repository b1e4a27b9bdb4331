/* SHA-1 (FIPS 180-4) and base64 (RFC 4648), only as much as the WebSocket handshake needs to
 * check the server's Sec-WebSocket-Accept. */
#include <string.h>

#include "embedded_internal.h"

static uint32_t rotate(uint32_t value, int bits)
{
    return value << bits | value >> (32 - bits);
}

static void sha1_block(uint32_t state[5], const uint8_t block[64])
{
    uint32_t w[80];
    for (int i = 0; i < 16; ++i) {
        w[i] = (uint32_t)block[4 * i] << 24 | (uint32_t)block[4 * i + 1] << 16 |
               (uint32_t)block[4 * i + 2] << 8 | block[4 * i + 3];
    }
    for (int i = 16; i < 80; ++i) {
        w[i] = rotate(w[i - 3] ^ w[i - 8] ^ w[i - 14] ^ w[i - 16], 1);
    }
    uint32_t a = state[0], b = state[1], c = state[2], d = state[3], e = state[4];
    for (int i = 0; i < 80; ++i) {
        uint32_t f, k;
        if (i < 20) {
            f = (b & c) | (~b & d);
            k = 0x5A827999;
        } else if (i < 40) {
            f = b ^ c ^ d;
            k = 0x6ED9EBA1;
        } else if (i < 60) {
            f = (b & c) | (b & d) | (c & d);
            k = 0x8F1BBCDC;
        } else {
            f = b ^ c ^ d;
            k = 0xCA62C1D6;
        }
        uint32_t t = rotate(a, 5) + f + e + k + w[i];
        e = d;
        d = c;
        c = rotate(b, 30);
        b = a;
        a = t;
    }
    state[0] += a;
    state[1] += b;
    state[2] += c;
    state[3] += d;
    state[4] += e;
}

void ubii__sha1(const uint8_t *data, size_t size, uint8_t digest[20])
{
    uint32_t state[5] = {0x67452301, 0xEFCDAB89, 0x98BADCFE, 0x10325476, 0xC3D2E1F0};
    size_t done = 0;
    for (; size - done >= 64; done += 64) {
        sha1_block(state, data + done);
    }
    uint8_t tail[128];
    size_t rest = size - done;
    memset(tail, 0, sizeof tail);
    memcpy(tail, data + done, rest);
    tail[rest] = 0x80;
    size_t blocks = rest + 9 > 64 ? 2 : 1;
    uint64_t bits = (uint64_t)size * 8;
    for (int i = 0; i < 8; ++i) {
        tail[blocks * 64 - 1 - (size_t)i] = (uint8_t)(bits >> (8 * i));
    }
    for (size_t i = 0; i < blocks; ++i) {
        sha1_block(state, tail + 64 * i);
    }
    for (int i = 0; i < 20; ++i) {
        digest[i] = (uint8_t)(state[i / 4] >> (24 - 8 * (i % 4)));
    }
}

size_t ubii__base64(const uint8_t *bytes, size_t size, char *out)
{
    static const char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t written = 0;
    for (size_t i = 0; i < size; i += 3) {
        uint32_t triple = (uint32_t)bytes[i] << 16;
        if (i + 1 < size) {
            triple |= (uint32_t)bytes[i + 1] << 8;
        }
        if (i + 2 < size) {
            triple |= bytes[i + 2];
        }
        out[written++] = alphabet[triple >> 18 & 63];
        out[written++] = alphabet[triple >> 12 & 63];
        out[written++] = i + 1 < size ? alphabet[triple >> 6 & 63] : '=';
        out[written++] = i + 2 < size ? alphabet[triple & 63] : '=';
    }
    out[written] = '\0';
    return written;
}

void ubii__websocket_accept(const char *key, char accept[32])
{
    static const char guid[] = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";
    uint8_t joined[64];
    size_t key_size = strlen(key);
    memcpy(joined, key, key_size);
    memcpy(joined + key_size, guid, sizeof guid - 1);
    uint8_t digest[20];
    ubii__sha1(joined, key_size + sizeof guid - 1, digest);
    ubii__base64(digest, sizeof digest, accept);
}
