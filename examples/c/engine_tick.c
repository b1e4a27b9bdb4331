/* engine_tick: a game engine's frame loop at 60 Hz drives a node. The loop sleeps in poll(2) on
 * the node's file descriptors (so it wakes at once when data arrives), bounded by the end of the
 * frame and the node's next deadline, then lets the node do its work with ubii_node_poll(node, 0),
 * which never blocks. Each frame publishes a pose; the node also receives it back.
 *
 *   engine_tick [SERVICE_URL [TOPIC_URL [SECONDS]]]   defaults: tcp://127.0.0.1:8101
 * tcp://127.0.0.1:8103 3 */
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <time.h>

#include "example_args.h"
#include "ubii/dataStructure/pose3d.pb.h"
#include "ubii/port_linux.h"
#include "ubii/ubii.h"

enum { FRAME_RATE = 60, MAX_FDS = 16 };

static double seconds_now(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + (double)now.tv_nsec / 1e9;
}

static void on_pose(ubii_node *node, const ubii_record *record, void *user)
{
    (void)node;
    (void)record;
    ++*(int *)user;
}

/* Waits for the node's fds until `until` (or the node's own deadline), as an engine would between
 * frames. */
static void wait_for_node(ubii_node *node, double until)
{
    ubii_pollfd node_fds[MAX_FDS];
    struct pollfd fds[MAX_FDS];
    int count = ubii_node_pollfds(node, node_fds, MAX_FDS);
    if (count > MAX_FDS) {
        count = MAX_FDS;
    }
    for (int i = 0; i < count; ++i) {
        fds[i].fd = node_fds[i].fd;
        fds[i].events = node_fds[i].events;
        fds[i].revents = 0;
    }
    int frame_left = (int)((until - seconds_now()) * 1000.0);
    int node_deadline = ubii_node_next_timeout_ms(node);
    int timeout = frame_left < 0 ? 0 : frame_left;
    if (node_deadline >= 0 && node_deadline < timeout) {
        timeout = node_deadline;
    }
    poll(fds, (nfds_t)count, timeout);
}

int main(int argc, char **argv)
{
    example_args args = example_parse_args(argc, argv, 3.0);
    ubii_linux_port_options options = {0};
    options.libwebsockets_log_level = 1;
    /* The default tcp:// engine runs in this thread, as the frame loop pumps it: no libzmq I/O
     * thread wakes for every message. */
    ubii_linux_port *port = NULL;
    if (ubii_linux_port_create(&port, &options) != UBII_OK) {
        return 1;
    }
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = args.service_url;
    config.topic_url = args.topic_url;
    config.client_name = "libubii-example-engine";
    static ubii_node node;
    ubii_node_init(&node, sizeof node, &config, ubii_linux_port_get(port));
    int received = 0;
    ubii_subscribe(&node, "/libubii/example/engine/pose", on_pose, &received, NULL);
    ubii_node_start(&node);

    const double frame = 1.0 / FRAME_RATE;
    double start = seconds_now();
    double next_frame = start;
    int frames = 0, published = 0;
    double busiest_poll = 0;
    while (seconds_now() - start < args.seconds) {
        next_frame += frame;
        /* The engine's own work would go here; then a pose per frame. */
        if (ubii_node_state(&node) == UBII_STATE_READY) {
            double t = seconds_now() - start;
            ubii_dataStructure_Pose3D pose = ubii_dataStructure_Pose3D_init_zero;
            pose.has_position = true;
            pose.position.x = cos(t);
            pose.position.y = sin(t);
            pose.which_orientation = ubii_dataStructure_Pose3D_euler_tag;
            pose.orientation.euler.z = t;
            if (ubii_publish_pose3d(&node, "/libubii/example/engine/pose", &pose) == UBII_OK) {
                published++;
            }
        }
        /* Sleep until the next frame, waking for network traffic. */
        while (seconds_now() < next_frame) {
            wait_for_node(&node, next_frame);
            double before = seconds_now();
            ubii_node_poll(&node, 0);
            double spent = seconds_now() - before;
            if (spent > busiest_poll) {
                busiest_poll = spent;
            }
        }
        frames++;
    }
    double elapsed = seconds_now() - start;
    printf("engine_tick: %d frames in %.2f s (%.1f Hz), %s, published %d poses, received %d back, "
           "longest ubii_node_poll(node, 0): %.3f ms\n",
           frames, elapsed, frames / elapsed, ubii_state_name(ubii_node_state(&node)), published,
           received, busiest_poll * 1000.0);
    ubii_node_stop_wait(&node, 2000);
    ubii_linux_port_destroy(port);
    return published > 0 && received > 0 ? 0 : 1;
}
