# Makes TinyXML (libtinyxml-dev, which urdfdom itself uses) available as the target
# adsd::tinyxml: it reads SRDF files and a URDF's joint order. TinyXML has no package config, so
# the library is found here, by the build and by the installed adsdConfig.cmake alike: a static
# adsd::planner then names this target, found again on the user's machine, not the path it had on
# the build machine.
if(NOT TARGET adsd::tinyxml)
  find_path(ADSD_TINYXML_INCLUDE_DIR tinyxml.h)
  find_library(ADSD_TINYXML_LIBRARY tinyxml)
  if(NOT ADSD_TINYXML_INCLUDE_DIR OR NOT ADSD_TINYXML_LIBRARY)
    message(FATAL_ERROR "adsd: TinyXML not found (Debian: apt-get install libtinyxml-dev)")
  endif()
  add_library(adsd::tinyxml UNKNOWN IMPORTED GLOBAL)
  set_target_properties(adsd::tinyxml PROPERTIES
    IMPORTED_LOCATION "${ADSD_TINYXML_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${ADSD_TINYXML_INCLUDE_DIR}")
endif()
