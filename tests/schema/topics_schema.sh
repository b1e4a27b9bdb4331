#!/usr/bin/env bash
# The reduced "topics" schema (UBII_SCHEMA=topics) end to end, from a full-schema build's test
# suite: builds the embedded port with that schema in WORK_DIR, checks that the API of left-out
# types does not compile for a caller, runs its unit test (topics_schema_test) and runs the
# static_node and pubsub examples against the running master (the `master` fixture).
#   topics_schema.sh SOURCE_DIR WORK_DIR PORT_BASE BUILD_TYPE SANITIZE MAX_MESSAGE FULL_GENERATED_DIR
set -euo pipefail
source=${1:?} work=${2:?} base=${3:?} build_type=${4:?} sanitize=${5:?} max_message=${6:?}
full_generated=${7:?}

cmake -S "$source" -B "$work" -DUBII_SCHEMA=topics -DUBII_PORT=embedded -DUBII_BUILD_TESTS=ON \
  -DUBII_BUILD_EXAMPLES=ON -DCMAKE_BUILD_TYPE="$build_type" -DUBII_SANITIZE="$sanitize" \
  -DUBII_EMBEDDED_MAX_MESSAGE="$max_message" >"$work.configure.log" 2>&1 ||
  { cat "$work.configure.log"; exit 1; }
cmake --build "$work" -j 2 --target static_node pubsub topics_schema_test >"$work.build.log" 2>&1 ||
  { cat "$work.build.log"; exit 1; }

# Same wire format: every field the topics schema generates is in the full schema with the same
# number, label (singular, repeated, oneof member), type and allocation: nanopb's FIELDLIST lines,
# each prefixed with its message.
fields() {
  find "$1" -name '*.pb.h' -print0 | sort -z | xargs -0 cat | awk '
    /_FIELDLIST\(X, a\)/ { message = $2; sub(/_FIELDLIST.*/, "", message) }
    /^X\(a,/ { line = $0; gsub(/[ \\]+/, "", line); print message " " line }' | sort -u
}
fields "$work/proto/generated" >"$work/topics.fields"
fields "$full_generated" >"$work/full.fields"
if [ ! -s "$work/topics.fields" ] || comm -23 "$work/topics.fields" "$work/full.fields" | grep .; then
  echo "topics_schema: the fields above are not the full schema's"; exit 1
fi
echo "topics_schema: $(wc -l <"$work/topics.fields") fields, each as in the full schema"

# A caller of a left-out type's API gets a compile error (C99 with -pedantic-errors, where calling
# an undeclared function is one; in C++ it always is). The first snippet must compile, so that the
# others fail for the right reason.
includes=(-I"$source/core/include" -I"$work/core/include" -I"$work/proto/generated" -I"$work/nanopb")
compiles() {
  printf '#include "ubii/ubii.h"\n%s\n' "$1" >"$work/snippet.c"
  cc -std=c99 -pedantic-errors -Wall -Werror "${includes[@]}" -c "$work/snippet.c" \
    -o "$work/snippet.o" 2>"$work/snippet.log"
}
compiles 'int f(ubii_node *n, const ubii_dataStructure_Pose3D *p); int f(ubii_node *n, const ubii_dataStructure_Pose3D *p) { return ubii_publish_pose3d(n, "/t", p) + UBII_RECORD_COLOR; }' ||
  { echo "topics_schema: kept API does not compile:"; cat "$work/snippet.log"; exit 1; }
# Each snippet with the name its error message must give (so that it fails for that reason).
while IFS='|' read -r reason snippet; do
  if compiles "$snippet" || ! grep -q "$reason" "$work/snippet.log"; then
    echo "topics_schema: must fail to compile for want of $reason: $snippet"; cat "$work/snippet.log"; exit 1
  fi
done <<'SNIPPETS'
ubii_publish_doubles|int f(ubii_node *n); int f(ubii_node *n) { return ubii_publish_doubles(n, "/t", 0, 0); }
ubii_publish_image|int f(ubii_node *n); int f(ubii_node *n) { return ubii_publish_image(n, "/t", 0, 0, 0, 0, 0); }
ubii_image_view|int f(const ubii_record *r); int f(const ubii_record *r) { ubii_image_view v; return ubii_record_image(r, &v); }
ubii_record_list|int f(const ubii_record *r); int f(const ubii_record *r) { return ubii_record_list(r, 0, 0); }
UBII_RECORD_IMAGE2D|int f(void); int f(void) { return UBII_RECORD_IMAGE2D; }
UBII_RECORD_MATRIX4X4|int f(void); int f(void) { return UBII_RECORD_MATRIX4X4; }
UBII_RECORD_DOUBLE_LIST|int f(void); int f(void) { return UBII_RECORD_DOUBLE_LIST; }
ubii_deregister_device|int f(ubii_node *n); int f(ubii_node *n) { return ubii_deregister_device(n, "d", 0, 0, 0); }
ubii_dataStructure_Object2D|int f(void); int f(void) { return (int)sizeof(ubii_dataStructure_Object2D); }
lists.pb.h|#include "ubii/lists.h"
image.pb.h|#include "ubii/image.h"
device.pb.h|#include "ubii/devices.h"
processingModule.pb.h|#include "ubii/processing.h"
ubii_node_offer_processing_modules|int f(ubii_node *n); int f(ubii_node *n) { return ubii_node_offer_processing_modules(n, 0, 0); }
SNIPPETS
echo "topics_schema: the API of left-out types does not compile"

"$work/tests/topics_schema_test"
service="tcp://127.0.0.1:$base"
"$work/examples/static_node" "$service" "tcp://127.0.0.1:$((base + 2))"
"$work/examples/static_node" "$service" "ws://127.0.0.1:$((base + 3))"
"$work/examples/pubsub" "$service" "tcp://127.0.0.1:$((base + 2))" 1 | tail -n 1
"$work/examples/pubsub" "$service" "ws://127.0.0.1:$((base + 3))" 1 | tail -n 1
echo "topics_schema: reduced-schema node exchanged records with the master"
