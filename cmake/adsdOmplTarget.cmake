# Makes OMPL available as the target ompl::ompl, which adsd::planner links. OMPL 2.0's package
# config defines that target itself; OMPL 1.5's only sets OMPL_INCLUDE_DIRS and OMPL_LIBRARIES,
# so the target is made from them. Run after find_package(ompl), by the build and by the installed
# adsdConfig.cmake alike, so that the exported adsd::planner names no path of the build machine.
if(NOT TARGET ompl::ompl)
  add_library(ompl::ompl INTERFACE IMPORTED GLOBAL)
  set_target_properties(ompl::ompl PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OMPL_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${OMPL_LIBRARIES}")
endif()
