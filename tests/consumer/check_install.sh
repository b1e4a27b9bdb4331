#!/usr/bin/env bash
# Installs the build tree BUILD_DIR into WORK/prefix, then builds and runs the consumer application
# against it three ways: find_package with the static library, with the shared library, and
# pkg-config; on the Linux port also a program and an engine plugin .so using the port, with
# pkg-config ubii (shared) and ubii-static (libubii inside, none of its symbols exported); with cpp, a C++ consumer both with find_package(ubii COMPONENTS cpp) and pkg-config
# ubii-cpp.
#   check_install.sh BUILD_DIR WORK [ocr] [cpp] [testing]   (ocr: the build has the OCR pipelines,
#     cpp: the C++ layer, also via pkg-config; testing: build examples/testing against the
#     installation and run it, its master started by the installed scripts)
set -euo pipefail
# grep reads its whole input (no -q): an early exit would fail the writer with SIGPIPE under pipefail.
build=${1:?} work=${2:?}
shift 2
ocr= cpp= testing=
for part in "$@"; do
  case $part in
    ocr) ocr=ocr ;;
    cpp) cpp=cpp ;;
    testing) testing=testing ;;
    "") ;; # a part the build does not have
    *) echo "check_install: unknown part $part" >&2; exit 2 ;;
  esac
done
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" >"$work/install.log"

consumer_ocr=OFF
[ "$ocr" = ocr ] && consumer_ocr=ON
consumer_cpp=OFF
[ "$cpp" = cpp ] && consumer_cpp=ON
cmake -S "$here" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DUBII_CONSUMER_OCR=$consumer_ocr -DUBII_CONSUMER_CPP=$consumer_cpp >"$work/configure.log"
cmake --build "$work/cmake-build" >"$work/build.log"
"$work/cmake-build/consumer_static"
if nm -D "$work/cmake-build/consumer_static" 2>/dev/null | grep ubii_ >/dev/null; then
  echo "check_install: consumer_static resolves libubii symbols dynamically" >&2
  exit 1
fi
libdir=$(dirname "$(find "$prefix" -name 'libubii.so' | head -n 1)")
LD_LIBRARY_PATH="$libdir" "$work/cmake-build/consumer_shared"
LD_LIBRARY_PATH="$libdir" ldd "$work/cmake-build/consumer_shared" | grep -F "$libdir/libubii.so" >/dev/null || {
  echo "check_install: consumer_shared does not load $libdir/libubii.so" >&2
  exit 1
}

flags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs ubii)
cc -std=c99 -Wall -Werror "$here/consumer.c" $flags -o "$work/consumer_pkgconfig"
LD_LIBRARY_PATH="$libdir" "$work/consumer_pkgconfig"
if [ -f "$prefix/include/ubii/port_linux.h" ]; then
  # The README's two forms with the port in use: ubii (the shared library) for a program, and
  # ubii-static for a program and for an engine plugin .so that carries libubii inside.
  LD_LIBRARY_PATH="$libdir" cc -std=c99 -Wall -Werror "$here/consumer_port.c" $flags \
    -o "$work/consumer_port_shared"
  LD_LIBRARY_PATH="$libdir" "$work/consumer_port_shared"
  static_flags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs ubii-static)
  cc -std=c99 -Wall -Werror "$here/consumer_port.c" $static_flags -o "$work/consumer_port_static"
  "$work/consumer_port_static"
  cc -std=c99 -Wall -Werror -shared -fPIC -DCONSUMER_PLUGIN "$here/consumer_port.c" $static_flags \
    -o "$work/consumer_plugin.so"
  # The host links what the plugin's flags link too: in a sanitized build the sanitizer runtime
  # must be the process's own, not come with a plugin.
  cc -std=c99 -Wall -Werror "$here/consumer_plugin_host.c" $static_flags -ldl \
    -o "$work/consumer_plugin_host"
  "$work/consumer_plugin_host" "$work/consumer_plugin.so"
  for binary in consumer_port_static consumer_plugin.so; do
    if ldd "$work/$binary" | grep -F libubii >/dev/null; then
      echo "check_install: $binary loads a shared libubii instead of carrying it" >&2
      exit 1
    fi
  done
  exported=$(nm -D --defined-only "$work/consumer_plugin.so" | awk '{print $NF}' |
    { grep -E '^(ubii_|pb_|zmq_|lws_)' || [ $? -eq 1 ]; })
  if [ -n "$exported" ]; then
    echo "check_install: the plugin exports libubii's symbols:" $exported >&2
    exit 1
  fi
fi
if [ "$consumer_ocr" = ON ]; then
  OMP_THREAD_LIMIT=1 "$work/cmake-build/consumer_ocr"
fi
if [ "$consumer_cpp" = ON ]; then
  "$work/cmake-build/consumer_cpp"
  cpp_flags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs ubii-cpp)
  # Sanitized builds put the sanitizer runtimes into ubii-cpp.pc's Libs already.
  c++ -Wall -Werror "$here/consumer_cpp.cpp" $cpp_flags -o "$work/consumer_cpp_pkgconfig"
  # ubii-cpp.pc names the shared layer on the shared libubii: one C core in the process.
  for lib in libubii_cpp.so libubii.so; do
    ldd "$work/consumer_cpp_pkgconfig" | grep -F "$lib" | grep -F "$prefix/" >/dev/null || {
      echo "check_install: consumer_cpp_pkgconfig does not load $lib from $prefix" >&2
      exit 1
    }
  done
  "$work/consumer_cpp_pkgconfig"
fi
if [ "$testing" = testing ]; then
  # examples/testing as a user builds it: find_package(ubii COMPONENTS testing) from the prefix,
  # its fixture starting the master with the installed scripts.
  cmake -S "${UBII_CONSUMER_TESTING_SOURCE:?}" -B "$work/testing-build" -DCMAKE_PREFIX_PATH="$prefix" \
    >"$work/testing-configure.log"
  cmake --build "$work/testing-build" >"$work/testing-build.log"
  UBII_TESTING_SCRIPTS= "$work/testing-build/scale_test" >"$work/testing-run.log" 2>&1 || {
    cat "$work/testing-run.log" >&2
    exit 1
  }
  grep -F "[  PASSED  ] 2 tests" "$work/testing-run.log" >/dev/null || {
    echo "check_install: the installed fixture's example did not pass both tests:" >&2
    cat "$work/testing-run.log" >&2
    exit 1
  }
fi
parts="static, shared"
[ "$consumer_ocr" = ON ] && parts="$parts, ocr"
[ "$consumer_cpp" = ON ] && parts="$parts, cpp"
[ "$testing" = testing ] && parts="$parts, testing"
echo "check_install: find_package ($parts) and pkg-config consumers work"
