cmake_minimum_required(VERSION 3.25)
# Fails when a layer includes a header of a layer above it (GUIDE,
# "Architecture"). Run as: cmake -DROOT=<source dir> -P tests/layering.cmake
# Each entry: a folder and the folders its sources may include from.
set(layers
  "core:core"
  "rewriting:core,rewriting"
  "io:core,rewriting,io"
  "checkers:core,rewriting,checkers"
  "generators:core,rewriting,io,generators"
  "proofs:core,rewriting,checkers,proofs"
  "reports:core,rewriting,io,checkers,generators,proofs,events,inference,querymodify,analysis,reports"
  "events:core,rewriting,checkers,events"
  "inference:core,rewriting,io,checkers,inference"
  "querymodify:core,rewriting,io,checkers,querymodify"
  "analysis:core,rewriting,io,checkers,generators,proofs,events,analysis"
  "compiler:core,rewriting,checkers,compiler"
  "campaign:core,rewriting,io,checkers,generators,proofs,events,inference,querymodify,analysis,reports,campaign"
  # fuzz/ harnesses sit on top like the tests (fuzz_shard reads what campaign/ writes).
  "fuzz:core,rewriting,io,checkers,generators,proofs,events,inference,querymodify,analysis,reports,campaign,fuzz"
  # The command, the benchmarks and the tests sit on top: they may use every
  # library, but the command nothing test- or benchmark-only, and the
  # benchmarks and tests not the command's own files.
  "cli:core,rewriting,io,checkers,generators,proofs,reports,events,inference,querymodify,analysis,campaign,compiler,cli"
  "bench:core,rewriting,io,checkers,generators,proofs,reports,events,inference,querymodify,analysis,bench"
  "tests:core,rewriting,io,checkers,generators,proofs,reports,events,inference,querymodify,analysis,campaign,compiler,cli,tests")
set(known core rewriting io checkers generators proofs reports events inference querymodify analysis campaign compiler cli fuzz bench tests)
set(errors 0)
set(checked 0)
foreach(entry IN LISTS layers)
  string(REPLACE ":" ";" parts "${entry}")
  list(GET parts 0 layer)
  list(GET parts 1 allowed)
  string(REPLACE "," ";" allowed "${allowed}")
  file(GLOB_RECURSE sources "${ROOT}/${layer}/*.hpp" "${ROOT}/${layer}/*.cpp")
  foreach(source IN LISTS sources)
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" target "${line}")
      if(target IN_LIST known AND NOT target IN_LIST allowed)
        file(RELATIVE_PATH rel "${ROOT}" "${source}")
        message(SEND_ERROR "${rel}: includes ${target}/, a layer above ${layer}/ (${line})")
        math(EXPR errors "${errors} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()
if(errors GREATER 0)
  message(FATAL_ERROR "${errors} upward include(s)")
endif()
message(STATUS "layering: ${checked} files, no upward include")
