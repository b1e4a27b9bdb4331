#!/usr/bin/env bash
# OCR accuracy on the evaluation set (36 generated images the pipelines were never tuned on):
# builds ocr_eval (Release) and prints precision / recall per pipeline and scene kind, beside the
# tesseract CLI as installed. Asserts nothing.
#   bench/ocr/eval.sh [--pipelines pure,pure-auto,mser,db,cli-sparse,cli-auto]
#                     [--east-model frozen_east_text_detection.pb] [--save DIR] [--verbose]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench-ocr"

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/ocr-models.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_WITH_OCR=ON \
  -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target ocr_eval >/dev/null
OMP_THREAD_LIMIT=${OMP_THREAD_LIMIT:-1} exec "$build/bench/ocr/ocr_eval" "$@"
