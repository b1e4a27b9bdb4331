#ifndef UBII_UBII_H
#define UBII_UBII_H

/* Everything an application of the C core needs, for the schema it was built with. */

#include "ubii/config.h"
#include "ubii/node.h"
#include "ubii/port.h"
#include "ubii/service.h"
#include "ubii/status.h"
#include "ubii/topic.h"
#include "ubii/url.h"
#include "ubii/version.h"
#include "ubii/wire.h"
/* Generated: the optional parts of the API (lists.h, image.h, devices.h) the schema has. */
#include "ubii/schema_api.h"

#endif
