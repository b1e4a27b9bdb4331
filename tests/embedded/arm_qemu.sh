#!/usr/bin/env bash
# Cross-compiles the embedded build's examples for 32-bit ARM (gcc-arm-linux-gnueabihf) and runs
# them under qemu-arm against the master: static_node (every allocation trapped) over ZMTP and
# over WebSocket, and pubsub. Exit 77 (skipped) if the cross tools are missing.
#   arm_qemu.sh SOURCE_DIR WORK_DIR PORT_BASE
set -euo pipefail
source=${1:?} work=${2:?} base=${3:?}
for tool in arm-linux-gnueabihf-gcc qemu-arm; do
  command -v "$tool" >/dev/null || { echo "arm_qemu: $tool missing (scripts/bootstrap.sh installs it): skipped"; exit 77; }
done
cmake -S "$source" -B "$work" -DCMAKE_TOOLCHAIN_FILE="$source/cmake/toolchains/arm-linux-gnueabihf.cmake" \
  -DUBII_PORT=embedded -DUBII_BUILD_TESTS=OFF -DUBII_BUILD_EXAMPLES=ON -DCMAKE_BUILD_TYPE=MinSizeRel \
  >"$work.configure.log" 2>&1 || { cat "$work.configure.log"; exit 1; }
cmake --build "$work" -j 2 --target static_node pubsub >"$work.build.log" 2>&1 || { cat "$work.build.log"; exit 1; }
file "$work/examples/static_node" | grep -q "ARM" || { echo "arm_qemu: not an ARM binary"; exit 1; }
run() { qemu-arm -L /usr/arm-linux-gnueabihf "$@"; }
service="tcp://127.0.0.1:$base"
run "$work/examples/static_node" "$service" "tcp://127.0.0.1:$((base + 2))"
run "$work/examples/static_node" "$service" "ws://127.0.0.1:$((base + 3))"
run "$work/examples/pubsub" "$service" "tcp://127.0.0.1:$((base + 2))" 1 | tail -n 1
echo "arm_qemu: ARM binaries exchanged records with the master"
