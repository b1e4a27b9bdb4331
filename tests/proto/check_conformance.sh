#!/usr/bin/env bash
# Compiles the official msg-formats schema (installed from npm by scripts/npm-packages.sh) into a
# descriptor set and compares it, message by message, with ours.
#   check_conformance.sh MSG_FORMATS_PACKAGE_DIR OUR_DESCRIPTOR_SET REFERENCE_OUT
set -euo pipefail
package=${1:?} ours=${2:?} reference=${3:?}
if [ ! -d "$package/src/proto" ]; then
  echo "check_conformance: no reference schema in $package (run scripts/npm-packages.sh)" >&2
  exit 1
fi
(cd "$package/src" && protoc -I . --include_imports --descriptor_set_out="$reference" \
  $(find proto -name '*.proto' | sort) 2>/dev/null)
exec /usr/bin/python3 "$(dirname "$0")/compare_schemas.py" "$reference" "$ours"
