# One folder for everything fetched at build or test time (nanopb sources, npm packages), shared by
# build trees so that a second build or a CI rerun fetches nothing.
if(DEFINED ENV{UBII_CACHE_DIR})
  set(_ubii_cache_default "$ENV{UBII_CACHE_DIR}")
elseif(DEFINED ENV{XDG_CACHE_HOME})
  set(_ubii_cache_default "$ENV{XDG_CACHE_HOME}/libubii")
else()
  set(_ubii_cache_default "$ENV{HOME}/.cache/libubii")
endif()
set(UBII_CACHE_DIR "${_ubii_cache_default}" CACHE PATH "Folder for fetched sources and npm packages")
