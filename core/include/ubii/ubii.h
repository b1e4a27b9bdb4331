#ifndef UBII_UBII_H
#define UBII_UBII_H

/* Everything an application of the C core needs. */

#include "ubii/config.h"
#include "ubii/node.h"
#include "ubii/port.h"
#include "ubii/service.h"
#include "ubii/status.h"
#include "ubii/topic.h"
#include "ubii/version.h"
#include "ubii/wire.h"

#endif
