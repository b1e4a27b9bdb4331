#include "ubii/version.h"

const char *ubii_version(void)
{
    return UBII_VERSION_STRING;
}
