#include "ubii/ocr/omp.hpp"

#include <cstdlib>

#include <unistd.h>

namespace ubii::ocr
{

bool ensure_single_omp_thread(int argc, char **argv)
{
    if (std::getenv("OMP_THREAD_LIMIT") != nullptr)
        return true;
    if (argc < 1 || argv == nullptr || argv[0] == nullptr)
        return false;
    // Set before the exec so that the new image's libgomp reads it when it loads; the variable
    // also stops a second re-exec.
    if (setenv("OMP_THREAD_LIMIT", "1", 1) != 0)
        return false;
    execv("/proc/self/exe", argv);
    return false; // exec failed: carry on with the threads libgomp already chose
}

} // namespace ubii::ocr
