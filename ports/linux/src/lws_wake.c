/* The port's wake-up eventfd inside libwebsockets: while lws drives the wait, a write to the
 * eventfd from another thread (ubii_linux_port_wake) must end lws_service() at once. */
#include <string.h>
#include <unistd.h>

#include "lws_internal.h"

int ubii__lws_on_wake(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                      size_t len)
{
    (void)in;
    (void)len;
    lws_wake_record *record = user;
    if (record == NULL || record->kind != LWS_RECORD_WAKE) {
        return 0;
    }
    if (reason == LWS_CALLBACK_RAW_RX_FILE) {
        /* Reading resets the counter (the duplicate shares it), so the fd stops being readable
         * until the next wake. */
        uint64_t count;
        if (read(record->port->wake_fd, &count, sizeof count) < 0) {
            return 0; /* EAGAIN: another wait drained it first */
        }
    } else if (reason == LWS_CALLBACK_RAW_CLOSE_FILE) {
        LWS(record->port)->set_wsi_user(wsi, NULL);
    }
    return 0;
}

void ubii__lws_adopt_wake(ubii_linux_port *port)
{
    if (port->lws == NULL || port->wake_fd < 0) {
        return;
    }
    /* lws closes what it adopts: it gets a duplicate, and the port keeps its own fd. */
    lws_adopt_desc_t desc;
    memset(&desc, 0, sizeof desc);
    desc.vh = port->vhost;
    desc.type = LWS_ADOPT_RAW_FILE_DESC;
    desc.fd.filefd = dup(port->wake_fd);
    desc.vh_prot_name = "ubii-wake";
    struct lws *wsi =
        desc.fd.filefd >= 0 ? LWS(port)->adopt_descriptor_vhost_via_info(&desc) : NULL;
    if (wsi == NULL) {
        /* lws failed before taking the fd: the wait then still ends by its timeout. */
        if (desc.fd.filefd >= 0) {
            close(desc.fd.filefd);
        }
        return;
    }
    port->wake_record.kind = LWS_RECORD_WAKE;
    port->wake_record.port = port;
    LWS(port)->set_wsi_user(wsi, &port->wake_record);
}
