/* Bounded string copies into the node's fixed-size fields and nanopb's char arrays. */
#include <string.h>

#include "copy_string.h"

bool ubii__copy_string(char *destination, size_t capacity, const char *source)
{
    size_t length = strlen(source);
    if (length >= capacity) {
        return false;
    }
    memcpy(destination, source, length + 1);
    return true;
}
