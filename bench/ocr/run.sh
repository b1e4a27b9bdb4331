#!/usr/bin/env bash
# OCR benchmark: builds ocr_bench (Release) and prints the table of per-frame times for every
# pipeline on every synthetic scene, beside the tesseract CLI, a bare TessBaseAPI call and the
# thesis's figures. Asserts nothing.
#   bench/ocr/run.sh [--frames N] [--cli-runs N] [--east-model frozen_east_text_detection.pb]
#                    [--east-input WxH] [--save DIR]
# Without --east-model there are no EAST rows (no EAST model ships; the generated test network
# the tests use is no text detector). DB runs scripts/ocr-models.sh's model.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench-ocr"

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/ocr-models.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_WITH_OCR=ON \
  -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target ocr_bench >/dev/null
# Set here as well as by ocr_bench's own re-exec: the tesseract CLI it starts inherits it.
OMP_THREAD_LIMIT=${OMP_THREAD_LIMIT:-1} exec "$build/bench/ocr/ocr_bench" "$@"
