// Prints what ensure_single_omp_thread left behind: the limit, how many times main() ran (counted
// through an environment variable the re-executed image inherits) and the arguments it got.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ubii/ocr/omp.hpp"

int main(int argc, char **argv)
{
    const char *previous_runs = std::getenv("UBII_OCR_PROBE_RUNS");
    const int runs = (previous_runs != nullptr ? std::atoi(previous_runs) : 0) + 1;
    setenv("UBII_OCR_PROBE_RUNS", std::to_string(runs).c_str(), 1);

    ubii::ocr::ensure_single_omp_thread(argc, argv);

    std::string args;
    for (int i = 1; i < argc; ++i)
        args += (i > 1 ? "|" : "") + std::string(argv[i]);
    const char *limit = std::getenv("OMP_THREAD_LIMIT");
    std::printf("OMP_THREAD_LIMIT=%s runs=%d args=%s\n", limit != nullptr ? limit : "(unset)", runs,
                args.c_str());
    return 0;
}
