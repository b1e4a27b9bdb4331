/* Uses an installed libubii the way an application does: its own API, and the schema with nanopb's
 * functions (which reach libubii's prefixed copy through the installed headers). */
#include <stdio.h>
#include <string.h>

#include <pb_decode.h>

#include "ubii/service_codec.h"
#include "ubii/services/serviceRequest.pb.h"
#include "ubii/version.h"

int main(void)
{
    uint8_t bytes[128];
    size_t length = 0;
    if (ubii_encode_topic_request("/services/topic_list", bytes, sizeof bytes, &length) !=
        UBII_OK) {
        fprintf(stderr, "consumer: encoding failed\n");
        return 1;
    }
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    pb_istream_t stream = pb_istream_from_buffer(bytes, length);
    if (!pb_decode(&stream, ubii_services_ServiceRequest_fields, &request) ||
        strcmp(request.topic, "/services/topic_list") != 0) {
        fprintf(stderr, "consumer: round trip failed\n");
        return 1;
    }
    printf("consumer: libubii %s round-tripped %s (%zu bytes)\n", ubii_version(), request.topic,
           length);
    return 0;
}
