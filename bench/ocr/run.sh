#!/usr/bin/env bash
# OCR benchmarks (Release build in build/bench-ocr); each prints a Markdown table, asserts nothing.
#   bench/ocr/run.sh [--frames N] [--cli-runs N] [--east-model PB] [--east-input WxH] [--save DIR]
#       per-frame times of every pipeline on the tuning scenes, beside the tesseract CLI, a bare
#       TessBaseAPI call and the thesis's figures (ocr_bench); EAST rows only with --east-model
#       (no EAST model ships; the tests' generated network is no text detector)
#   bench/ocr/run.sh eval [--pipelines pure,pure-auto,mser,db,cli-sparse,cli-auto]
#                         [--east-model PB] [--save DIR] [--verbose]
#       precision / recall on the evaluation set per pipeline and scene kind (ocr_eval)
#   bench/ocr/run.sh modules [--frames N]
#       each OCR module through a scheduler against its pipeline called directly (ocr_module_bench)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${UBII_BUILD_DIR:-$root/build}/bench-ocr"

program=ocr_bench
case "${1:-}" in
  eval) program=ocr_eval; shift ;;
  modules) program=ocr_module_bench; shift ;;
esac

"$root/scripts/bootstrap.sh" >/dev/null
"$root/scripts/ocr-models.sh" >/dev/null
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUBII_BUILD_BENCH=ON -DUBII_WITH_OCR=ON \
  -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target "$program" >/dev/null
# Set here as well as by the programs' own re-exec: the tesseract CLI they start inherits it.
OMP_THREAD_LIMIT=${OMP_THREAD_LIMIT:-1} exec "$build/bench/ocr/$program" "$@"
