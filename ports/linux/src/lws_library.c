/* libwebsockets through dlopen (lws_library.h says why). */
#include "lws_library.h"

#include <dlfcn.h>
#include <string.h>

#include "dynamic_library.h"

/* The soname of the libwebsockets whose header this was built with (CMake finds it), then the
 * unversioned name, which only exists with libwebsockets-dev. */
static const char *const library_names[] = {UBII_LWS_SONAME, "libwebsockets.so"};

/* Each pointer has the type of the function it will hold, as libwebsockets.h declares it: a
 * mismatch fails the build instead of the call. __typeof__ takes no address: nothing links. */
#define SAME_TYPE(function, member)                                                                \
    typedef char                                                                                   \
        member##_has_the_type_of_##function[__builtin_types_compatible_p(                          \
                                                __typeof__(&function),                             \
                                                __typeof__(((ubii__lws_library *)0)->member))      \
                                                ? 1                                                \
                                                : -1]
SAME_TYPE(lws_set_log_level, set_log_level);
SAME_TYPE(lws_create_context, create_context);
SAME_TYPE(lws_context_destroy, context_destroy);
SAME_TYPE(lws_get_vhost_by_name, get_vhost_by_name);
SAME_TYPE(lws_service, service);
SAME_TYPE(lws_sul_schedule, sul_schedule);
SAME_TYPE(lws_sul_cancel, sul_cancel);
SAME_TYPE(lws_client_connect_via_info, client_connect_via_info);
SAME_TYPE(lws_adopt_descriptor_vhost_via_info, adopt_descriptor_vhost_via_info);
SAME_TYPE(lws_set_wsi_user, set_wsi_user);
SAME_TYPE(lws_set_timeout, set_timeout);
SAME_TYPE(lws_get_context, get_context);
SAME_TYPE(lws_get_socket_fd, get_socket_fd);
SAME_TYPE(lws_get_random, get_random);
SAME_TYPE(lws_write, write);
SAME_TYPE(lws_callback_on_writable, callback_on_writable);
SAME_TYPE(lws_partial_buffered, partial_buffered);
SAME_TYPE(lws_send_pipe_choked, send_pipe_choked);
SAME_TYPE(lws_is_first_fragment, is_first_fragment);
SAME_TYPE(lws_is_final_fragment, is_final_fragment);
SAME_TYPE(lws_frame_is_binary, frame_is_binary);
SAME_TYPE(lws_remaining_packet_payload, remaining_packet_payload);
SAME_TYPE(lws_add_http_header_by_token, add_http_header_by_token);
SAME_TYPE(lws_add_http_header_content_length, add_http_header_content_length);
SAME_TYPE(lws_client_http_body_pending, client_http_body_pending);
SAME_TYPE(lws_http_client_http_response, http_client_http_response);
SAME_TYPE(lws_http_client_read, http_client_read);

#define RESOLVE(function, member)                                                                  \
    ubii__library_resolve(handle, "libwebsockets", #function, &loaded.member, error, error_size)

bool ubii__lws_library_load(ubii__lws_library *library, char *error, size_t error_size)
{
    if (library->handle != NULL) {
        return true;
    }
    /* Never unmapped (NODELETE): OpenSSL, which it brings, keeps process-wide state and exit
     * handlers that must outlive any one port. */
    void *handle = ubii__library_open(library_names, sizeof library_names / sizeof library_names[0],
                                      RTLD_NODELETE, "libwebsockets", error, error_size);
    if (handle == NULL) {
        return false;
    }
    ubii__lws_library loaded;
    memset(&loaded, 0, sizeof loaded);
    loaded.handle = handle;
    bool complete =
        RESOLVE(lws_set_log_level, set_log_level) && RESOLVE(lws_create_context, create_context) &&
        RESOLVE(lws_context_destroy, context_destroy) &&
        RESOLVE(lws_get_vhost_by_name, get_vhost_by_name) && RESOLVE(lws_service, service) &&
        RESOLVE(lws_sul_schedule, sul_schedule) && RESOLVE(lws_sul_cancel, sul_cancel) &&
        RESOLVE(lws_client_connect_via_info, client_connect_via_info) &&
        RESOLVE(lws_adopt_descriptor_vhost_via_info, adopt_descriptor_vhost_via_info) &&
        RESOLVE(lws_set_wsi_user, set_wsi_user) && RESOLVE(lws_set_timeout, set_timeout) &&
        RESOLVE(lws_get_context, get_context) && RESOLVE(lws_get_socket_fd, get_socket_fd) &&
        RESOLVE(lws_get_random, get_random) && RESOLVE(lws_write, write) &&
        RESOLVE(lws_callback_on_writable, callback_on_writable) &&
        RESOLVE(lws_partial_buffered, partial_buffered) &&
        RESOLVE(lws_send_pipe_choked, send_pipe_choked) &&
        RESOLVE(lws_is_first_fragment, is_first_fragment) &&
        RESOLVE(lws_is_final_fragment, is_final_fragment) &&
        RESOLVE(lws_frame_is_binary, frame_is_binary) &&
        RESOLVE(lws_remaining_packet_payload, remaining_packet_payload) &&
        RESOLVE(lws_add_http_header_by_token, add_http_header_by_token) &&
        RESOLVE(lws_add_http_header_content_length, add_http_header_content_length) &&
        RESOLVE(lws_client_http_body_pending, client_http_body_pending) &&
        RESOLVE(lws_http_client_http_response, http_client_http_response) &&
        RESOLVE(lws_http_client_read, http_client_read);
    if (!complete) {
        dlclose(handle);
        return false;
    }
    *library = loaded;
    return true;
}

void ubii__lws_library_unload(ubii__lws_library *library)
{
    if (library->handle != NULL) {
        dlclose(library->handle);
    }
    memset(library, 0, sizeof *library);
}
