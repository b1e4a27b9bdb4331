/* Descriptors that are not libwebsockets' own inside its wait: while lws drives the wait, each
 * libzmq socket's fd, each in-thread ZMTP connection's and the port's wake-up eventfd is adopted
 * into it (as a duplicate: lws closes what it adopts), so that their traffic ends lws_service()
 * as well. Their owners do their own I/O after the wait. */
#define _POSIX_C_SOURCE 200809L /* dup */

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <zmq.h>

#include "lws_internal.h"

void ubii__lws_adopt_fd(ubii_linux_port *port, const void *owner, int fd, void *zmq_socket)
{
    if (port->lws == NULL || owner == NULL || fd < 0) {
        return;
    }
    for (int i = 0; i < MAX_FOREIGN_FDS; ++i) {
        if (port->foreign_fds[i] != NULL) {
            continue;
        }
        foreign_fd *adopted = calloc(1, sizeof *adopted);
        if (adopted == NULL) {
            return;
        }
        lws_adopt_desc_t desc;
        memset(&desc, 0, sizeof desc);
        desc.vh = port->vhost;
        desc.type = LWS_ADOPT_RAW_FILE_DESC;
        desc.fd.filefd = dup(fd);
        desc.vh_prot_name = "ubii-foreign-fd";
        adopted->kind = LWS_RECORD_FOREIGN_FD;
        adopted->port = port;
        adopted->owner = owner;
        adopted->zmq_socket = zmq_socket;
        port->foreign_fds[i] = adopted;
        adopted->wsi =
            desc.fd.filefd >= 0 ? LWS(port)->adopt_descriptor_vhost_via_info(&desc) : NULL;
        if (adopted->wsi == NULL) {
            /* lws closes a file descriptor it failed to adopt only if it is a socket's. */
            if (desc.fd.filefd >= 0) {
                close(desc.fd.filefd);
            }
            port->foreign_fds[i] = NULL;
            free(adopted);
            return;
        }
        LWS(port)->set_wsi_user(adopted->wsi, adopted);
        return;
    }
}

void ubii__lws_adopt_zmq(ubii_linux_port *port, void *socket)
{
    int fd = -1;
    size_t length = sizeof fd;
    if (port->lws != NULL && socket != NULL &&
        port->zmq_api.getsockopt(socket, ZMQ_FD, &fd, &length) == 0) {
        ubii__lws_adopt_fd(port, socket, fd, socket);
    }
}

static foreign_fd *adopted_for(ubii_linux_port *port, const void *owner, int *slot)
{
    for (int i = 0; owner != NULL && i < MAX_FOREIGN_FDS; ++i) {
        if (port->foreign_fds[i] != NULL && port->foreign_fds[i]->owner == owner) {
            *slot = i;
            return port->foreign_fds[i];
        }
    }
    return NULL;
}

void ubii__lws_release_fd(ubii_linux_port *port, const void *owner)
{
    int slot;
    foreign_fd *adopted = adopted_for(port, owner, &slot);
    if (adopted == NULL) {
        return;
    }
    /* Its callback must not touch the owner, about to close; the record goes with the wsi. */
    adopted->owner = NULL;
    adopted->zmq_socket = NULL;
    port->foreign_fds[slot] = NULL;
    if (adopted->wsi != NULL) {
        LWS(port)->set_timeout(adopted->wsi, PENDING_TIMEOUT_USER_OK, LWS_TO_KILL_SYNC);
    } else {
        free(adopted);
    }
}

void ubii__lws_want_writable(ubii_linux_port *port, const void *owner)
{
    int slot;
    foreign_fd *adopted = adopted_for(port, owner, &slot);
    if (adopted != NULL && adopted->wsi != NULL) {
        LWS(port)->callback_on_writable(adopted->wsi);
    }
}

int ubii__lws_on_foreign_fd(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                            size_t len)
{
    (void)in;
    (void)len;
    foreign_fd *adopted = user;
    if (adopted == NULL || adopted->kind != LWS_RECORD_FOREIGN_FD) {
        return 0;
    }
    if (reason == LWS_CALLBACK_RAW_RX_FILE && adopted->zmq_socket != NULL) {
        /* Reading ZMQ_EVENTS lets libzmq consume its signal, so the fd stops being readable. */
        int events = 0;
        size_t length = sizeof events;
        adopted->port->zmq_api.getsockopt(adopted->zmq_socket, ZMQ_EVENTS, &events, &length);
    } else if (reason == LWS_CALLBACK_RAW_CLOSE_FILE) {
        LWS(adopted->port)->set_wsi_user(wsi, NULL);
        if (adopted->owner == NULL) {
            free(adopted); /* released: nobody else holds it */
        } else {
            adopted->wsi = NULL;
        }
    }
    /* A ZMTP connection's bytes stay in its socket for the port to read after the wait. */
    return 0;
}
