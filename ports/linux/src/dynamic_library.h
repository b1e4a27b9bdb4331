#ifndef UBII_DYNAMIC_LIBRARY_H
#define UBII_DYNAMIC_LIBRARY_H

/* What zmq_library.c and lws_library.c share: opening a library by the first of its names that
 * loads, and resolving its functions one by one, each failure said in `error`. */

#include <stdbool.h>
#include <stddef.h>

/* dlopen's handle of the first of `names` that loads (RTLD_NOW | RTLD_LOCAL | `flags`), or NULL
 * with "`what` could not be loaded: ..." in `error`. */
void *ubii__library_open(const char *const *names, size_t count, int flags, const char *what,
                         char *error, size_t error_size);
/* Stores the address of `name` into the function pointer at `function`; false, with "`what` has
 * no `name`" in `error`, if the library lacks it. */
bool ubii__library_resolve(void *handle, const char *what, const char *name, void *function,
                           char *error, size_t error_size);

#endif
