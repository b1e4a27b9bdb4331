#ifndef UBII_EXPORT_H
#define UBII_EXPORT_H

/* UBII_API marks the symbols a shared libubii exports; everything else is built with hidden
 * visibility. A static build (UBII_STATIC defined by the build system's interface) needs no marker.
 */
#if defined(UBII_STATIC)
#define UBII_API
#elif defined(_WIN32)
#if defined(UBII_BUILDING)
#define UBII_API __declspec(dllexport)
#else
#define UBII_API __declspec(dllimport)
#endif
#else
#define UBII_API __attribute__((visibility("default")))
#endif

#endif
