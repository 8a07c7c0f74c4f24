# The LAMMPS the plugin is built against, described from LAMMPS itself.
#
# A plugin must be compiled with the definitions LAMMPS was compiled with: they
# fix the layout of LAMMPS' classes (LAMMPS_SMALLBIG, LAMMPS_MEMALIGN, LMP_KOKKOS,
# LMP_KOKKOS_LAYOUT_*, ...). LAMMPS makes most of them PRIVATE to its `lammps`
# target, so even the LAMMPS::lammps target of an installed LAMMPS (whose
# LAMMPSConfig.cmake only exists after `cmake --install`) carries only
# LAMMPS_SMALLBIG, and an installed LAMMPS has only library.h of its headers. So
# we read them where they are complete: from the compile line of LAMMPS' own
# src/lammps.cpp in its build tree (build.ninja for Ninja, flags.make for
# Makefiles), together with its include folders and C++ standard, and the Kokkos
# it used from its CMakeCache.txt.
#
# In:  LAMMPS_SOURCE_DIR (with src/ and cmake/), LAMMPS_BUILD_DIR (a CMake build
#      of it with BUILD_SHARED_LIBS=on, PKG_KOKKOS and PKG_PLUGIN)
# Out: imported target `lammps`, LAMMPS_VERSION_STRING ("4 Jul 2026"),
#      GRANSPH_LAMMPS_VERSION (20260704), LAMMPS_CXX_STANDARD, LAMMPS_KOKKOS_DIR,
#      LAMMPS_MPI (off: LAMMPS' MPI stubs), LAMMPS_BINARY

# --- version, from src/version.h ("#define LAMMPS_VERSION "29 Sep 2021"")
file(STRINGS "${LAMMPS_SOURCE_DIR}/src/version.h" _version_line REGEX "define LAMMPS_VERSION ")
if(NOT _version_line MATCHES "\"([0-9]+) ([A-Za-z]+) ([0-9]+)\"")
  message(FATAL_ERROR "Cannot read the LAMMPS version from ${LAMMPS_SOURCE_DIR}/src/version.h")
endif()
set(_day ${CMAKE_MATCH_1})
set(_year ${CMAKE_MATCH_3})
set(LAMMPS_VERSION_STRING "${CMAKE_MATCH_1} ${CMAKE_MATCH_2} ${CMAKE_MATCH_3}")
set(_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
list(FIND _months "${CMAKE_MATCH_2}" _month)
if(_month EQUAL -1)
  message(FATAL_ERROR "Unknown month in LAMMPS version '${LAMMPS_VERSION_STRING}'")
endif()
math(EXPR _month "${_month} + 1")
if(_month LESS 10)
  set(_month "0${_month}")
endif()
if(_day LESS 10)
  set(_day "0${_day}")
endif()
set(GRANSPH_LAMMPS_VERSION "${_year}${_month}${_day}")
set(GRANSPH_TESTED_LAMMPS 20210929 20260704)
if(NOT GRANSPH_LAMMPS_VERSION IN_LIST GRANSPH_TESTED_LAMMPS)
  message(WARNING "LAMMPS ${LAMMPS_VERSION_STRING} is not one of the versions GRANSPH is tested "
                  "with (29 Sep 2021, 4 Jul 2026): it may not compile")
endif()

# --- LAMMPS' own compile line for src/lammps.cpp
set(_defines "")
set(_includes "")
set(_flags "")
if(EXISTS "${LAMMPS_BUILD_DIR}/build.ninja")
  file(READ "${LAMMPS_BUILD_DIR}/build.ninja" _ninja)
  string(REGEX MATCH "\nbuild CMakeFiles/lammps\\.dir/[^\n]*/src/lammps\\.cpp\\.o:[^\n]*\n(  [^\n]*\n)*" _block "${_ninja}")
  unset(_ninja)
  string(REGEX MATCH "\n  DEFINES = ([^\n]*)" _m "${_block}")
  set(_defines "${CMAKE_MATCH_1}")
  string(REGEX MATCH "\n  INCLUDES = ([^\n]*)" _m "${_block}")
  set(_includes "${CMAKE_MATCH_1}")
  string(REGEX MATCH "\n  FLAGS = ([^\n]*)" _m "${_block}")
  set(_flags "${CMAKE_MATCH_1}")
elseif(EXISTS "${LAMMPS_BUILD_DIR}/CMakeFiles/lammps.dir/flags.make")
  file(STRINGS "${LAMMPS_BUILD_DIR}/CMakeFiles/lammps.dir/flags.make" _lines)
  foreach(_l IN LISTS _lines)
    if(_l MATCHES "^CXX_DEFINES = (.*)")
      set(_defines "${CMAKE_MATCH_1}")
    elseif(_l MATCHES "^CXX_INCLUDES = (.*)")
      set(_includes "${CMAKE_MATCH_1}")
    elseif(_l MATCHES "^CXX_FLAGS = (.*)")
      set(_flags "${CMAKE_MATCH_1}")
    endif()
  endforeach()
endif()
if(_defines STREQUAL "" OR _includes STREQUAL "")
  message(FATAL_ERROR "Cannot find how LAMMPS compiled src/lammps.cpp in ${LAMMPS_BUILD_DIR} "
                      "(build.ninja or CMakeFiles/lammps.dir/flags.make): is it a CMake build tree?")
endif()

string(REGEX MATCHALL "-D[^ ]+" _defs "${_defines}")
list(TRANSFORM _defs REPLACE "^-D" "")
# the shared library's export macro is LAMMPS' own, not an interface
list(FILTER _defs EXCLUDE REGEX "_EXPORTS$")
set(LAMMPS_COMPILE_DEFINITIONS ${_defs})
# LAMMPS' own include folders (-I); MPI's and Kokkos' (-isystem) come with their targets
string(REGEX MATCHALL " -I[^ ]+" _incs " ${_includes}")
list(TRANSFORM _incs REPLACE "^ -I" "")
set(LAMMPS_INCLUDE_DIRS ${_incs})
if(_flags MATCHES "-std=(c|gnu)\\+\\+([0-9]+)")
  set(LAMMPS_CXX_STANDARD ${CMAKE_MATCH_2})
else()
  set(LAMMPS_CXX_STANDARD 17)
endif()

foreach(_required LMP_KOKKOS LMP_PLUGIN)
  if(NOT _required IN_LIST LAMMPS_COMPILE_DEFINITIONS)
    message(FATAL_ERROR "LAMMPS in ${LAMMPS_BUILD_DIR} was built without ${_required}: "
                        "GRANSPH needs PKG_KOKKOS=on and PKG_PLUGIN=on")
  endif()
endforeach()

# --- the library, and the Kokkos LAMMPS was configured with
find_library(LAMMPS_LIBRARY NAMES lammps PATHS "${LAMMPS_BUILD_DIR}" NO_DEFAULT_PATH)
if(NOT LAMMPS_LIBRARY OR NOT LAMMPS_LIBRARY MATCHES "\\.so")
  message(FATAL_ERROR "No shared liblammps in ${LAMMPS_BUILD_DIR} (build LAMMPS with BUILD_SHARED_LIBS=on)")
endif()
load_cache("${LAMMPS_BUILD_DIR}" READ_WITH_PREFIX LAMMPS_CACHE_ Kokkos_DIR EXTERNAL_KOKKOS BUILD_MPI)
if(NOT LAMMPS_CACHE_EXTERNAL_KOKKOS OR NOT LAMMPS_CACHE_Kokkos_DIR)
  message(FATAL_ERROR "LAMMPS in ${LAMMPS_BUILD_DIR} was not configured with EXTERNAL_KOKKOS=on: "
                      "GRANSPH's /kk styles must use the Kokkos installation LAMMPS used")
endif()
set(LAMMPS_KOKKOS_DIR "${LAMMPS_CACHE_Kokkos_DIR}")
set(LAMMPS_MPI ${LAMMPS_CACHE_BUILD_MPI})

set(LAMMPS_BINARY "${LAMMPS_BUILD_DIR}/lmp")

message(STATUS "LAMMPS ${LAMMPS_VERSION_STRING} (GRANSPH_LAMMPS_VERSION=${GRANSPH_LAMMPS_VERSION}) "
               "in ${LAMMPS_BUILD_DIR}, C++${LAMMPS_CXX_STANDARD}, Kokkos from ${LAMMPS_KOKKOS_DIR}")
message(STATUS "LAMMPS compile definitions: ${LAMMPS_COMPILE_DEFINITIONS}")
