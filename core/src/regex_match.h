#ifndef UBII_REGEX_MATCH_H
#define UBII_REGEX_MATCH_H

/* regex.c: the topic regex dialect both masters accept. Internal to the core; not installed. */

#include "ubii/status.h"

#include <stdbool.h>
#include <stdint.h>

/* UBII_OK match, UBII_ERR_NOT_FOUND no match, or why it cannot run. */
ubii_status ubii__regex_search(const char *pattern, const char *text, uint32_t step_limit);
/* Checks that the pattern is within the supported dialect (without matching anything). */
ubii_status ubii__regex_validate(const char *pattern);

#endif
