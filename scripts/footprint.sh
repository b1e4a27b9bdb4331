#!/usr/bin/env bash
# Footprint of the embedded build (core + schema + nanopb runtime + embedded port) at -Os, for
# x86-64 and 32-bit ARM: code (.text), initialised data, zero data, and the static RAM of the
# documented default configuration (8 subscriptions, 2 KB messages): sizeof(ubii_node) +
# sizeof(ubii_embedded_port). Each with the full schema and with the reduced "topics" schema
# (UBII_SCHEMA=topics, proto/schemas/topics.schema). A report, not a test.
#   scripts/footprint.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out="${UBII_BUILD_DIR:-$root/build}/footprint"
config=(-DUBII_MAX_SUBSCRIPTIONS=8 -DUBII_MAX_TOPIC_SIZE=128 -DUBII_MAX_URL_SIZE=64
        -DUBII_SERVICE_QUEUE_BYTES=1024 -DUBII_SERVICE_QUEUE_DEPTH=4)
flags="${config[*]}"

measure() {
  local name=$1 schema=$2; shift 2
  local dir="$out/$name-$schema"
  cmake -S "$root" -B "$dir" -DUBII_PORT=embedded -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=OFF \
    -DCMAKE_BUILD_TYPE=MinSizeRel -DCMAKE_C_FLAGS="$flags" -DUBII_SCHEMA="$schema" "$@" >/dev/null
  cmake --build "$dir" -j "$(nproc)" --target ubii_core ubii_schema ubii_nanopb ubii_port_embedded >/dev/null
  local objects
  objects=$(find "$dir" -name '*.o' \( -path '*ubii_core.dir*' -o -path '*ubii_schema.dir*' \
            -o -path '*ubii_nanopb.dir*' -o -path '*ubii_port_embedded.dir*' \))
  local sizes
  sizes=$(size -t $objects | tail -n 1)
  # sizeof on the target itself (run under qemu for ARM).
  cat > "$dir/sizes.c" <<'C'
#include <stdio.h>
#include "ubii/port_embedded.h"
#include "ubii/ubii.h"
int main(void) { printf("%zu %zu\n", sizeof(ubii_node), sizeof(ubii_embedded_port)); return 0; }
C
  local cc=${CC_FOR_SIZES:-cc} runner=()
  if [ "$name" = "arm" ]; then cc=arm-linux-gnueabihf-gcc; runner=(qemu-arm -L /usr/arm-linux-gnueabihf); fi
  $cc -std=c99 $flags -I"$root/core/include" -I"$root/ports/embedded/include" -I"$dir/core/include" \
    -I"$dir/proto/generated" -I"$dir/nanopb" "$dir/sizes.c" -o "$dir/sizes"
  read -r node port < <("${runner[@]}" "$dir/sizes")
  echo "$sizes" | awk -v n="$name" -v s="$schema" -v node="$node" -v port="$port" \
    '{ printf "%-8s %-7s %8d %8d %8d %10d %10d %10d\n", n, s, $1, $2, $3, node, port, node + port + $3 }'
}

printf "%-8s %-7s %8s %8s %8s %10s %10s %10s\n" target schema text data bss "ubii_node" "port" "static RAM"
for schema in full topics; do
  measure x86-64 "$schema"
done
if command -v arm-linux-gnueabihf-gcc >/dev/null && command -v qemu-arm >/dev/null; then
  for schema in full topics; do
    measure arm "$schema" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/arm-linux-gnueabihf.cmake"
  done
fi
echo "config: ${config[*]} UBII_EMBEDDED_MAX_MESSAGE=2048"
echo "data: the schema's constant tables (read-only after relocation; flash on a microcontroller), not RAM"
