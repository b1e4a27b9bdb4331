/* libzmq's sockets inside the lws wait: each socket's fd is adopted into lws (as a dup'd raw
 * descriptor) so that ZMQ traffic ends lws_service() as well. */
#define _POSIX_C_SOURCE 200809L /* dup */

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <zmq.h>

#include "lws_internal.h"

void ubii__lws_adopt_zmq(ubii_linux_port *port, void *socket)
{
    if (port->lws == NULL || socket == NULL) {
        return;
    }
    int fd = -1;
    size_t length = sizeof fd;
    if (port->zmq_api.getsockopt(socket, ZMQ_FD, &fd, &length) != 0) {
        return;
    }
    for (int i = 0; i < MAX_ZMQ_WAKEUPS; ++i) {
        if (port->wakeups[i] != NULL) {
            continue;
        }
        zmq_wakeup *wakeup = calloc(1, sizeof *wakeup);
        if (wakeup == NULL) {
            return;
        }
        /* lws closes what it adopts: it gets a duplicate, never libzmq's own fd. */
        lws_adopt_desc_t desc;
        memset(&desc, 0, sizeof desc);
        desc.vh = port->vhost;
        desc.type = LWS_ADOPT_RAW_FILE_DESC;
        desc.fd.filefd = dup(fd);
        desc.vh_prot_name = "ubii-zmq-wakeup";
        desc.opaque = wakeup;
        wakeup->port = port;
        wakeup->socket = socket;
        port->wakeups[i] = wakeup;
        wakeup->wsi = desc.fd.filefd >= 0 ? lws_adopt_descriptor_vhost_via_info(&desc) : NULL;
        if (wakeup->wsi == NULL) {
            port->wakeups[i] = NULL;
            free(wakeup);
        }
        return;
    }
}

void ubii__lws_release_zmq(ubii_linux_port *port, void *socket)
{
    for (int i = 0; i < MAX_ZMQ_WAKEUPS; ++i) {
        zmq_wakeup *wakeup = port->wakeups[i];
        if (wakeup == NULL || wakeup->socket != socket) {
            continue;
        }
        wakeup->socket = NULL; /* its callback must not touch the socket about to close */
        port->wakeups[i] = NULL;
        if (wakeup->wsi != NULL) {
            lws_set_timeout(wakeup->wsi, PENDING_TIMEOUT_USER_OK, LWS_TO_KILL_SYNC);
        } else {
            free(wakeup);
        }
    }
}

/* Reading ZMQ_EVENTS when a dup'd fd fires lets libzmq consume its signal. */
int ubii__lws_on_zmq_wakeup(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                            size_t len)
{
    (void)user;
    (void)in;
    (void)len;
    zmq_wakeup *wakeup = lws_get_opaque_user_data(wsi);
    if (wakeup == NULL) {
        return 0;
    }
    if (reason == LWS_CALLBACK_RAW_RX_FILE && wakeup->socket != NULL) {
        /* Reading ZMQ_EVENTS lets libzmq consume its signal, so the fd stops being readable. */
        int events = 0;
        size_t length = sizeof events;
        wakeup->port->zmq_api.getsockopt(wakeup->socket, ZMQ_EVENTS, &events, &length);
    } else if (reason == LWS_CALLBACK_RAW_CLOSE_FILE) {
        lws_set_opaque_user_data(wsi, NULL);
        if (wakeup->socket == NULL) {
            free(wakeup); /* released: nobody else holds it */
        } else {
            wakeup->wsi = NULL;
        }
    }
    return 0;
}
