# Copies the schema's .proto files below ubii/messages/ and points their imports there, so that the
# C++ code protoc generates (ubii/messages/<dir>/<file>.pb.h) never shares a path with the C code
# nanopb generates (ubii/<dir>/<file>.pb.h). Packages, messages and field numbers are untouched:
# only the file names change, which the wire never sees.
#   cmake -DSOURCE_DIR=proto/ubii -DSTAGE_DIR=<build>/messages-proto -P stage_protos.cmake
file(GLOB_RECURSE protos RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*.proto")
foreach(proto IN LISTS protos)
  file(READ "${SOURCE_DIR}/${proto}" text)
  string(REPLACE "import \"ubii/" "import \"ubii/messages/" text "${text}")
  set(target "${STAGE_DIR}/ubii/messages/${proto}")
  # Unchanged files keep their time stamp, so protoc does not rerun for nothing.
  if(EXISTS "${target}")
    file(READ "${target}" old)
    if(old STREQUAL text)
      continue()
    endif()
  endif()
  file(WRITE "${target}" "${text}")
endforeach()
