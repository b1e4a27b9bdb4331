#!/usr/bin/env bash
# The OCR modules' wrapping cost: builds ocr_module_bench (Release) and prints, per module and
# synthetic scene, the per-frame time through a scheduler (record in, worker pass, Object2DList
# out) beside its pipeline called directly, timed alternately. Asserts nothing.
#   bench/ocr/module_bench.sh [--frames N]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench-ocr"

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/ocr-models.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_WITH_OCR=ON \
  -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target ocr_module_bench ubii_ocr_modules >/dev/null
OMP_THREAD_LIMIT=${OMP_THREAD_LIMIT:-1} exec "$build/bench/ocr/ocr_module_bench" "$@"
