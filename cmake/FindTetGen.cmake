# Finds TetGen 1.5 as a library (Debian: libtet1.5-dev), providing TetGen::TetGen. TetGen
# ships no CMake configuration of its own. Include tetgen.h with TETLIBRARY defined.
find_path(TetGen_INCLUDE_DIR NAMES tetgen.h)
find_library(TetGen_LIBRARY NAMES tet)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(TetGen REQUIRED_VARS TetGen_INCLUDE_DIR TetGen_LIBRARY)
if(TetGen_FOUND AND NOT TARGET TetGen::TetGen)
  add_library(TetGen::TetGen UNKNOWN IMPORTED)
  set_target_properties(TetGen::TetGen PROPERTIES IMPORTED_LOCATION "${TetGen_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${TetGen_INCLUDE_DIR}")
endif()
mark_as_advanced(TetGen_INCLUDE_DIR TetGen_LIBRARY)
