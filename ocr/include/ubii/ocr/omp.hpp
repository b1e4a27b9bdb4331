#ifndef UBII_OCR_OMP_HPP
#define UBII_OCR_OMP_HPP

namespace ubii::ocr
{

// Debian's Tesseract is built with OpenMP. With more than one thread it is several times slower
// on a small machine and burns about five times the CPU for identical output, and libgomp reads
// OMP_THREAD_LIMIT only when it is loaded: setenv() in main() comes too late. Call this first
// thing in main(): when OMP_THREAD_LIMIT is not set, it sets it to 1 and re-executes the program
// (/proc/self/exe with the same argv), once. It returns when the variable was already set (then
// it leaves the user's value alone) and returns false if the re-exec failed, in which case the
// program continues, slower but correct. Alternatively set OMP_THREAD_LIMIT=1 in the launcher.
bool ensure_single_omp_thread(int argc, char **argv);

} // namespace ubii::ocr

#endif
