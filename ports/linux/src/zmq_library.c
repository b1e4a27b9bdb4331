/* libzmq through dlopen (zmq_library.h says why). */
#include "zmq_library.h"

#include <dlfcn.h>
#include <string.h>

#include "dynamic_library.h"

/* The soname Debian's libzmq5 installs; the unversioned name only exists with libzmq3-dev. */
static const char *const library_names[] = {"libzmq.so.5", "libzmq.so"};

static bool resolve(void *handle, const char *name, void *function, char *error, size_t error_size)
{
    return ubii__library_resolve(handle, "libzmq", name, function, error, error_size);
}

bool ubii__zmq_library_load(ubii__zmq_library *library, char *error, size_t error_size)
{
    if (library->handle != NULL) {
        return true;
    }
    void *handle = ubii__library_open(library_names, sizeof library_names / sizeof library_names[0],
                                      0, "libzmq", error, error_size);
    if (handle == NULL) {
        return false;
    }
    ubii__zmq_library loaded;
    memset(&loaded, 0, sizeof loaded);
    loaded.handle = handle;
    bool complete =
        resolve(handle, "zmq_ctx_new", &loaded.ctx_new, error, error_size) &&
        resolve(handle, "zmq_ctx_term", &loaded.ctx_term, error, error_size) &&
        resolve(handle, "zmq_socket", &loaded.socket, error, error_size) &&
        resolve(handle, "zmq_close", &loaded.close, error, error_size) &&
        resolve(handle, "zmq_connect", &loaded.connect, error, error_size) &&
        resolve(handle, "zmq_setsockopt", &loaded.setsockopt, error, error_size) &&
        resolve(handle, "zmq_getsockopt", &loaded.getsockopt, error, error_size) &&
        resolve(handle, "zmq_socket_monitor", &loaded.socket_monitor, error, error_size) &&
        resolve(handle, "zmq_msg_init", &loaded.msg_init, error, error_size) &&
        resolve(handle, "zmq_msg_init_size", &loaded.msg_init_size, error, error_size) &&
        resolve(handle, "zmq_msg_close", &loaded.msg_close, error, error_size) &&
        resolve(handle, "zmq_msg_data", &loaded.msg_data, error, error_size) &&
        resolve(handle, "zmq_msg_size", &loaded.msg_size, error, error_size) &&
        resolve(handle, "zmq_msg_more", &loaded.msg_more, error, error_size) &&
        resolve(handle, "zmq_msg_recv", &loaded.msg_recv, error, error_size) &&
        resolve(handle, "zmq_msg_send", &loaded.msg_send, error, error_size) &&
        resolve(handle, "zmq_poll", &loaded.poll, error, error_size) &&
        resolve(handle, "zmq_errno", &loaded.errno_, error, error_size);
    if (!complete) {
        dlclose(handle);
        return false;
    }
    *library = loaded;
    return true;
}

void ubii__zmq_library_unload(ubii__zmq_library *library)
{
    if (library->handle != NULL) {
        dlclose(library->handle);
    }
    memset(library, 0, sizeof *library);
}
