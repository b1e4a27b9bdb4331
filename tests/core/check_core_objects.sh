#!/usr/bin/env bash
# The core's promises, read off its object files (core, generated schema, nanopb runtime):
#  - no heap: no reference to malloc, calloc, realloc, free or C++ new/delete;
#  - no threads: no pthread symbol;
#  - no global or static mutable state: no symbol in .data or .bss;
#  - every exported symbol starts with ubii_.
# Usage: check_core_objects.sh OBJECT...
set -euo pipefail
# Symbols sanitizer instrumentation adds (UBII_SANITIZE builds) are not the code's own.
instrumentation='^(__odr_asan|__asan|___asan|__ubsan|__sancov)'
[ $# -gt 0 ] || { echo "usage: check_core_objects.sh OBJECT..." >&2; exit 2; }
failures=0

# The tools run on their own first: a tool that fails (a missing object, a file it cannot read)
# fails the check, instead of yielding no symbols that then look clean. Only grep's "no match"
# (exit 1) counts as an empty result.
undefined=$(nm -u "$@")
sections=$(objdump -t "$@")
defined=$(nm -g --defined-only "$@")
matching() { grep "$@" || [ $? -eq 1 ]; }

allocators=$(awk '{print $NF}' <<<"$undefined" |
  matching -E '^(malloc|calloc|realloc|free|aligned_alloc|posix_memalign|strdup|_Zn[wa]m|_Zd[la]Pv.*|pthread_.*)$' |
  sort -u)
if [ -n "$allocators" ]; then
  echo "check_core_objects: heap or thread functions referenced:" $allocators
  failures=1
fi

# Constant tables holding pointers sit in .data.rel.ro (read-only once relocated): not mutable.
mutable=$(awk '$0 ~ / O / { section = $(NF - 2); if (section ~ /^\.(data|bss)/ && section !~ /^\.data\.rel\.ro/) print $NF }' <<<"$sections" |
  matching -Ev "$instrumentation" | sort -u)
if [ -n "$mutable" ]; then
  echo "check_core_objects: writable global or static data:" $mutable
  failures=1
fi

foreign=$(awk 'NF == 3 {print $3}' <<<"$defined" | matching -v '^ubii_' |
  matching -Ev "$instrumentation" | sort -u)
if [ -n "$foreign" ]; then
  echo "check_core_objects: exported symbols without the ubii_ prefix:" $foreign
  failures=1
fi

[ $failures -eq 0 ] || exit 1
echo "check_core_objects: $# objects: no heap, no threads, no mutable global state, all exports ubii_"
