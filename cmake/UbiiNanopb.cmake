# nanopb: Debian's generator, and the runtime compiled from Debian's source package.
#
# Debian's prebuilt runtime (libprotobuf-nanopb.a) is built with PB_ENABLE_MALLOC; libubii's core must
# not allocate, so it compiles the three runtime files itself with the settings in UBII_NANOPB_DEFINES.
find_program(UBII_PROTOC protoc REQUIRED)
find_program(UBII_PROTOC_GEN_NANOPB protoc-gen-nanopb PATHS /usr/bin REQUIRED)
find_program(UBII_SYSTEM_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)

set(UBII_NANOPB_SOURCE_DIR "${UBII_CACHE_DIR}/nanopb-src" CACHE PATH "nanopb runtime sources")
if(NOT EXISTS "${UBII_NANOPB_SOURCE_DIR}/pb_decode.c")
  message(STATUS "Fetching the nanopb runtime sources (Debian source package) into ${UBII_NANOPB_SOURCE_DIR}")
  execute_process(
    COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/scripts/fetch-nanopb-source.sh" "${UBII_NANOPB_SOURCE_DIR}"
    RESULT_VARIABLE _ubii_fetch_result)
  if(NOT _ubii_fetch_result EQUAL 0)
    message(FATAL_ERROR "Could not fetch the nanopb runtime sources; run scripts/bootstrap.sh, "
                        "or set UBII_NANOPB_SOURCE_DIR to a folder holding pb_decode.c")
  endif()
endif()

# No PB_ENABLE_MALLOC: fields are static or callbacks, never heap (proto/README.md).
set(UBII_NANOPB_DEFINES "")

# The runtime is compiled from a copy whose pb.h first includes ubii/nanopb_prefix.h, which renames
# every nanopb function to ubii_pb_*; the same copies of the headers are installed. Quoted includes
# resolve beside the including file, so the .c files are copied too.
set(UBII_NANOPB_DIR "${CMAKE_BINARY_DIR}/nanopb")
foreach(file pb_common.h pb_common.c pb_encode.h pb_encode.c pb_decode.h pb_decode.c)
  configure_file("${UBII_NANOPB_SOURCE_DIR}/${file}" "${UBII_NANOPB_DIR}/${file}" COPYONLY)
endforeach()
file(READ "${UBII_NANOPB_SOURCE_DIR}/pb.h" _ubii_pb_h)
file(CONFIGURE OUTPUT "${UBII_NANOPB_DIR}/pb.h"
     CONTENT "/* nanopb's pb.h with libubii's symbol prefix applied first. */\n#include \"ubii/nanopb_prefix.h\"\n@_ubii_pb_h@"
     @ONLY)

add_library(ubii_nanopb OBJECT
  "${UBII_NANOPB_DIR}/pb_common.c"
  "${UBII_NANOPB_DIR}/pb_encode.c"
  "${UBII_NANOPB_DIR}/pb_decode.c")
target_include_directories(ubii_nanopb PUBLIC
  "$<BUILD_INTERFACE:${UBII_NANOPB_DIR}>"
  "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/core/include>"
  "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/ubii/schema>")
target_compile_definitions(ubii_nanopb PUBLIC ${UBII_NANOPB_DEFINES})
