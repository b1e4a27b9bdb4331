#ifndef UBII_COPY_STRING_H
#define UBII_COPY_STRING_H

/* copy_string.c: bounded copies into fixed-size fields. Internal to the core; not installed. */

#include <stdbool.h>
#include <stddef.h>

/* false, and nothing copied, when `source` does not fit. */
bool ubii__copy_string(char *destination, size_t capacity, const char *source);

#endif
