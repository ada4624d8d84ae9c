# dartcheck_missing_packages(OUT name...): the names among GTest, rapidcheck,
# CGAL, OpenMesh, benchmark and libpng that are not installed, found as the
# tests and benchmarks find them (quietly: the caller says what is missing).
function(dartcheck_missing_packages out)
  set(missing)
  foreach(name IN LISTS ARGN)
    if(name STREQUAL "libpng")
      find_package(PkgConfig QUIET)
      if(PkgConfig_FOUND)
        pkg_check_modules(DARTCHECK_PROBE_PNG QUIET libpng)
      endif()
      set(found ${DARTCHECK_PROBE_PNG_FOUND})
    elseif(name STREQUAL "OpenMesh")
      # Config mode: CGAL's FindOpenMesh module fails where OpenMesh's own
      # configuration is found.
      find_package(OpenMesh CONFIG QUIET)
      set(found ${OpenMesh_FOUND})
    else()
      find_package(${name} QUIET)
      set(found ${${name}_FOUND})
    endif()
    if(NOT found)
      list(APPEND missing ${name})
    endif()
  endforeach()
  set(${out} ${missing} PARENT_SCOPE)
endfunction()
