#ifndef UBII_LWS_LIBRARY_H
#define UBII_LWS_LIBRARY_H

/* libwebsockets, loaded when a port first opens a ws:// or http:// channel (or is created with
 * enable_tls) instead of at program start: a node that speaks only tcp:// never maps it, nor the
 * OpenSSL, zlib and libcap it pulls in (1.9 MiB resident in every node that linked them).
 * libwebsockets.h still gives the types and constants. */

#include <stdbool.h>
#include <stddef.h>

#include <libwebsockets.h>

typedef struct ubii__lws_library {
    void *handle; /* dlopen's; NULL until loaded */
    void (*set_log_level)(int level, void (*emit)(int level, const char *line));
    struct lws_context *(*create_context)(const struct lws_context_creation_info *info);
    void (*context_destroy)(struct lws_context *context);
    struct lws_vhost *(*get_vhost_by_name)(struct lws_context *context, const char *name);
    int (*service)(struct lws_context *context, int timeout_ms);
    void (*sul_schedule)(struct lws_context *context, int tsi, lws_sorted_usec_list_t *sul,
                         sul_cb_t callback, lws_usec_t us);
    void (*sul_cancel)(lws_sorted_usec_list_t *sul);
    struct lws *(*client_connect_via_info)(const struct lws_client_connect_info *info);
    struct lws *(*adopt_descriptor_vhost_via_info)(const lws_adopt_desc_t *info);
    void (*set_wsi_user)(struct lws *wsi, void *user);
    void (*set_timeout)(struct lws *wsi, enum pending_timeout reason, int seconds);
    struct lws_context *(*get_context)(const struct lws *wsi);
    lws_sockfd_type (*get_socket_fd)(struct lws *wsi);
    size_t (*get_random)(struct lws_context *context, void *buffer, size_t length);
    int (*write)(struct lws *wsi, unsigned char *buffer, size_t length,
                 enum lws_write_protocol protocol);
    int (*callback_on_writable)(struct lws *wsi);
    int (*partial_buffered)(struct lws *wsi);
    int (*send_pipe_choked)(struct lws *wsi);
    int (*is_first_fragment)(struct lws *wsi);
    int (*is_final_fragment)(struct lws *wsi);
    int (*frame_is_binary)(struct lws *wsi);
    size_t (*remaining_packet_payload)(struct lws *wsi);
    int (*add_http_header_by_token)(struct lws *wsi, enum lws_token_indexes token,
                                    const unsigned char *value, int length, unsigned char **p,
                                    unsigned char *end);
    int (*add_http_header_content_length)(struct lws *wsi, lws_filepos_t length, unsigned char **p,
                                          unsigned char *end);
    void (*client_http_body_pending)(struct lws *wsi, int something_left_to_send);
    unsigned int (*http_client_http_response)(struct lws *wsi);
    int (*http_client_read)(struct lws *wsi, char **buffer, int *length);
} ubii__lws_library;

/* Loads libwebsockets and every function above; false, with `error` filled in, if any is
 * missing. */
bool ubii__lws_library_load(ubii__lws_library *library, char *error, size_t error_size);
void ubii__lws_library_unload(ubii__lws_library *library);

#endif
