/* libFuzzer target: TopicData from the master, as the node handles it: every record found is
 * dispatched to a subscription whose callback tries every accessor on it. */
#include <string.h>

#include "record.h"
#include "ubii/image.h"
#include "ubii/lists.h"
#include "ubii/dataStructure/object2d.pb.h"
#include "ubii/dataStructure/pose3d.pb.h"

static ubii_status no_open(void *p, ubii_channel c, const char *u, const char *i)
{
    (void)p, (void)c, (void)u, (void)i;
    return UBII_OK;
}
static void no_close(void *p, ubii_channel c)
{
    (void)p, (void)c;
}
static ubii_channel_state open_state(void *p, ubii_channel c)
{
    (void)p, (void)c;
    return UBII_CHANNEL_OPEN;
}
static ubii_status no_send_begin(void *p, ubii_channel c, size_t s, uint8_t **b)
{
    (void)p, (void)c, (void)s, (void)b;
    return UBII_ERR_WOULD_BLOCK;
}
static ubii_status no_send_commit(void *p, ubii_channel c, unsigned f)
{
    (void)p, (void)c, (void)f;
    return UBII_ERR_STATE;
}
static ubii_status nothing_received(void *p, ubii_channel c, const uint8_t **d, size_t *s,
                                    unsigned *f)
{
    (void)p, (void)c, (void)d, (void)s, (void)f;
    return UBII_ERR_WOULD_BLOCK;
}
static ubii_status no_wait(void *p, int t)
{
    (void)p, (void)t;
    return UBII_OK;
}
static int no_fds(void *p, ubii_pollfd *f, int c)
{
    (void)p, (void)f, (void)c;
    return 0;
}
static uint64_t zero_ms(void *p)
{
    (void)p;
    return 0;
}
static int64_t zero_epoch(void *p)
{
    (void)p;
    return 0;
}

static const ubii_port_vtable stub = {no_open,        no_close,         open_state, no_send_begin,
                                      no_send_commit, nothing_received, no_wait,    no_fds,
                                      zero_ms,        zero_epoch};

static void try_everything(ubii_node *node, const ubii_record *record, void *user)
{
    (void)node, (void)user;
    double d;
    float f;
    int32_t i;
    bool b;
    const char *text;
    size_t length;
    ubii_record_double(record, &d);
    ubii_record_float(record, &f);
    ubii_record_int32(record, &i);
    ubii_record_bool(record, &b);
    ubii_record_string(record, &text, &length);
    ubii_dataStructure_Pose3D pose = ubii_dataStructure_Pose3D_init_zero;
    ubii_record_decode(record, UBII_RECORD_POSE3D, ubii_dataStructure_Pose3D_fields, &pose);
    ubii_dataStructure_Object2D object = ubii_dataStructure_Object2D_init_zero;
    ubii_record_decode(record, UBII_RECORD_OBJECT2D, ubii_dataStructure_Object2D_fields, &object);
    ubii_image_view image;
    ubii_record_image(record, &image);
    ubii_list_iter it;
    if (ubii_record_list(record, record->type, &it) == UBII_OK) {
        const uint8_t *bytes;
        size_t size;
        for (int n = 0; n < 1000 && ubii_list_next_double(&it, &d); ++n) {
        }
        ubii_record_list(record, record->type, &it);
        for (int n = 0; n < 1000 && ubii_list_next_int32(&it, &i); ++n) {
        }
        ubii_record_list(record, record->type, &it);
        for (int n = 0; n < 1000 && ubii_list_next_bytes(&it, &bytes, &size); ++n) {
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static ubii_node node;
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = "tcp://fuzz:1";
    config.topic_url = "tcp://fuzz:2";
    ubii_port port = {&stub, NULL};
    ubii_node_init(&node, sizeof node, &config, port);
    ubii_subscribe_regex(&node, ".*", try_everything, NULL, NULL);
    ubii_subscribe(&node, "/a", try_everything, NULL, NULL);
    node.state = UBII_STATE_READY; /* as if connected */
    node.subscriptions[0].at_master = 1;
    node.subscriptions[1].at_master = 1;
    ubii__handle_topic_data(&node, data, size);
    return 0;
}
