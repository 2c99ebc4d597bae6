# Installs the build into a fresh prefix, checks that no installed file names the build or source
# tree, then configures, builds and runs the consumer project against it (fmt's find-package test,
# for us). Arguments: BUILD_DIR, BUILD_TYPE, SOURCE_DIR (the consumer), PROJECT_SOURCE_DIR,
# WORK_DIR, WITH_PLANNER (ON/OFF).
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()

# An install must work after the trees it came from are gone: no installed file may name them.
# Programs and libraries are read without their debug sections (which name the sources by design),
# and only in builds without assertions: an assert's message names its source file.
if(BUILD_TYPE MATCHES "^(Release|MinSizeRel)$")
  set(check_binaries ON)
else()
  set(check_binaries OFF)
  message(STATUS "build type '${BUILD_TYPE}': programs and libraries not searched for the trees' paths")
endif()
find_program(OBJCOPY objcopy)
file(GLOB_RECURSE installed LIST_DIRECTORIES false "${WORK_DIR}/prefix/*")
foreach(f IN LISTS installed)
  file(READ "${f}" magic LIMIT 8 HEX)
  set(searched "${f}")
  if(magic MATCHES "^7f454c46" OR magic STREQUAL "213c617263683e0a")  # ELF, or an ar archive
    if(NOT check_binaries)
      continue()
    endif()
    if(NOT OBJCOPY)
      message(FATAL_ERROR "objcopy (binutils) is needed to read ${f} without its debug sections")
    endif()
    set(searched "${WORK_DIR}/without-debug")
    execute_process(COMMAND "${OBJCOPY}" --strip-debug "${f}" "${searched}" RESULT_VARIABLE rc)
    if(rc)
      message(FATAL_ERROR "objcopy --strip-debug ${f} failed: ${rc}")
    endif()
  endif()
  foreach(tree IN ITEMS "${BUILD_DIR}" "${PROJECT_SOURCE_DIR}")
    file(STRINGS "${searched}" hits REGEX "${tree}")
    if(hits)
      message(FATAL_ERROR "${f} names ${tree}")
    endif()
  endforeach()
endforeach()
file(REMOVE "${WORK_DIR}/without-debug")
# The exported targets name their dependencies by target, found again on the user's machine, never
# by a library file of the build machine (libtinyxml.so was one: a copied prefix needed that file).
file(GLOB exported "${WORK_DIR}/prefix/lib*/cmake/adsd/adsdTargets.cmake")
foreach(f IN LISTS exported)
  file(STRINGS "${f}" hits REGEX "INTERFACE_LINK_LIBRARIES.*/[^;\"]*\\.(so|a)[;\">]")
  if(hits)
    message(FATAL_ERROR "${f} links a library by its path: ${hits}")
  endif()
endforeach()

# Configures project SOURCE into WORK_DIR/BUILD against the installed prefix (with the further
# cache arguments given), builds it and runs its program PROGRAM, which must exit 0; WHAT names
# the project in the messages.
function(build_and_run what source build program)
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${source}" -B "${WORK_DIR}/${build}"
                          "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" -DCMAKE_BUILD_TYPE=Release ${ARGN}
                  RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "configuring ${what} failed: ${rc}")
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK_DIR}/${build}" RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "building ${what} failed: ${rc}")
  endif()
  execute_process(COMMAND "${WORK_DIR}/${build}/${program}" RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${what} answered wrongly: ${rc}")
  endif()
endfunction()

# A program of adsd::core alone asks for that component and needs Eigen alone: every other
# dependency hidden from it (it needed OMPL, FCL, urdfdom and the rest, an outside review found).
build_and_run("the core-only consumer" "${SOURCE_DIR}/../core_only" core_only core_only
              -DCMAKE_DISABLE_FIND_PACKAGE_ompl=ON -DCMAKE_DISABLE_FIND_PACKAGE_fcl=ON
              -DCMAKE_DISABLE_FIND_PACKAGE_assimp=ON -DCMAKE_DISABLE_FIND_PACKAGE_urdfdom=ON
              -DCMAKE_DISABLE_FIND_PACKAGE_yaml-cpp=ON -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON)
# An unknown component is refused by name, not with "adsd_FOUND set to FALSE" and no reason.
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/../core_only" -B "${WORK_DIR}/core_only_bad"
                        "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" -DASK_FOR=geometry
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc OR NOT out MATCHES "adsd has no component 'geometry' \\(this install has core")
  message(FATAL_ERROR "asking for component 'geometry': exit ${rc}, expected its refusal by name:\n${out}")
endif()

if(WITH_PLANNER)
  # An OMPL of another major.minor than the one adsd::planner was compiled against is refused at
  # configure time, naming both: it would link and then misbehave (OMPL's binary interface changes
  # with its minor version). OMPL 2.0 is not a Debian 12 package, so it is stood for by a package
  # config that only declares its version, which is all the check reads.
  set(other_ompl "${WORK_DIR}/ompl-2.0.2-config")
  file(WRITE "${other_ompl}/omplConfig.cmake" "set(OMPL_FOUND TRUE)\n")
  file(WRITE "${other_ompl}/omplConfigVersion.cmake"
       "set(PACKAGE_VERSION 2.0.2)\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/other_ompl"
                          "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-Dompl_DIR=${other_ompl}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc OR NOT out MATCHES "built against OMPL [0-9.]+, but OMPL '2\\.0\\.2' was found")
    message(FATAL_ERROR "an OMPL 2.0.2 package config: exit ${rc}, expected the version's refusal:\n${out}")
  endif()
endif()

build_and_run("the consumer" "${SOURCE_DIR}" build consumer "-DWITH_PLANNER=${WITH_PLANNER}")
if(WITH_PLANNER)
  # The installed program finds its shipped problems from its own location (PREFIX/share/adsd).
  # Certified motions: a discrete path, unseeded, may step over a corner, which `adsd plan`
  # reports as a contact (exit 1).
  execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=ADSD_PROBLEMS_DIR
                          "${WORK_DIR}/prefix/bin/adsd" plan --time 10 --motion certified
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "the installed adsd could not plan its default problem: ${rc}")
  endif()
  # An installed arm problem plans from the prefix too, when the robots are cached (tests/check.sh
  # fetches them); without them, the file must at least be there.
  set(arm_problem "${WORK_DIR}/prefix/share/adsd/problems/arm/kr5_table_pick/problem.cfg")
  if(NOT EXISTS "${arm_problem}" OR NOT EXISTS "${WORK_DIR}/prefix/share/adsd/fetch_robots.sh")
    message(FATAL_ERROR "the arm problems or fetch_robots.sh were not installed")
  endif()
  if(DEFINED ENV{ADSD_ROBOTS} AND NOT "$ENV{ADSD_ROBOTS}" STREQUAL "")
    set(robots "$ENV{ADSD_ROBOTS}")
  else()
    set(robots "$ENV{HOME}/.cache/adsd/robots")
  endif()
  if(EXISTS "${robots}/KR5/KR5 sixx R650.urdf")
    execute_process(COMMAND "${WORK_DIR}/prefix/bin/adsd" plan "${arm_problem}" --time 30 --seed 1
                    WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc)
    if(rc)
      message(FATAL_ERROR "the installed adsd could not plan the installed arm problem: ${rc}")
    endif()
  else()
    message(STATUS "robots not cached in ${robots}: the installed arm problem was not planned")
  endif()
  execute_process(COMMAND "${WORK_DIR}/build/plan_with_ompl" RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "the OMPL program did not plan a valid path with adsd's checker: ${rc}")
  endif()
endif()
