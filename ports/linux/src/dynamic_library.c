/* Libraries the Linux port loads at run time (dynamic_library.h). */
#include "dynamic_library.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

void *ubii__library_open(const char *const *names, size_t count, int flags, const char *what,
                         char *error, size_t error_size)
{
    void *handle = NULL;
    for (size_t i = 0; handle == NULL && i < count; ++i) {
        handle = dlopen(names[i], RTLD_NOW | RTLD_LOCAL | flags);
    }
    if (handle == NULL) {
        snprintf(error, error_size, "%s could not be loaded: %s", what, dlerror());
    }
    return handle;
}

bool ubii__library_resolve(void *handle, const char *what, const char *name, void *function,
                           char *error, size_t error_size)
{
    void *address = dlsym(handle, name);
    if (address == NULL) {
        snprintf(error, error_size, "%s has no %s", what, name);
        return false;
    }
    /* dlsym gives an object pointer; POSIX guarantees it converts to the function's type. */
    memcpy(function, &address, sizeof address);
    return true;
}
