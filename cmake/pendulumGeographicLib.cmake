# GeographicLib as the imported target GeographicLib::GeographicLib, the name
# GeographicLib's own CMake package gives it. Debian's libgeographiclib-dev
# ships no package configuration, so headers and library are looked up here.
# Used by the build and by the installed pendulumConfig.cmake, whose consumers
# link the static libpendulum and therefore GeographicLib too.
if(NOT TARGET GeographicLib::GeographicLib)
  find_path(GEOGRAPHICLIB_INCLUDE_DIR GeographicLib/NormalGravity.hpp)
  find_library(GEOGRAPHICLIB_LIBRARY NAMES GeographicLib)
  if(GEOGRAPHICLIB_INCLUDE_DIR AND GEOGRAPHICLIB_LIBRARY)
    add_library(GeographicLib::GeographicLib UNKNOWN IMPORTED)
    set_target_properties(GeographicLib::GeographicLib PROPERTIES
      IMPORTED_LOCATION "${GEOGRAPHICLIB_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${GEOGRAPHICLIB_INCLUDE_DIR}")
  endif()
endif()
