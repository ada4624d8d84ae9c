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
  "analysis:core,rewriting,io,checkers,generators,proofs,events,querymodify,analysis"
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

# Heavy headers (issues 36, 63): the Z3 C++ API, yaml-cpp and the whole
# JSON library are compiled only where they are used: in .cpp files, in a
# folder's detail/ headers (which the next rule keeps inside the folder)
# and, for JSON, in reports/json_document.hpp, which is itself included
# only by .cpp files and detail/ headers. Besides: yaml-cpp only in io/,
# z3++.h only in proofs/ (and their tests; the benchmarks may time the
# solver), RapidCheck only in tests/, CLI11 only in cli/command_line.cpp,
# and no JSON in cli/ (the commands state their parameters as
# campaign::Parameters; json_fwd.hpp declares the type).
set(heavy_headers "yaml-cpp/|z3\\+\\+.h|rapidcheck|CLI/|nlohmann/json.hpp|reports/json_document.hpp")
foreach(layer IN LISTS known)
  file(GLOB_RECURSE sources "${ROOT}/${layer}/*.hpp" "${ROOT}/${layer}/*.cpp")
  foreach(source IN LISTS sources)
    file(RELATIVE_PATH rel "${ROOT}" "${source}")
    file(STRINGS "${source}" includes REGEX "^#include [<\"](${heavy_headers})")
    set(private FALSE)  # a .cpp file, a detail/ header or a test
    if(rel MATCHES "\\.cpp$" OR rel MATCHES "/detail/[^/]*\\.hpp$" OR rel MATCHES "^tests/")
      set(private TRUE)
    endif()
    foreach(line IN LISTS includes)
      set(allowed FALSE)
      if(line MATCHES "yaml-cpp/")
        if(private AND rel MATCHES "^(tests/)?io/")
          set(allowed TRUE)
        endif()
      elseif(line MATCHES "z3")
        if(private AND rel MATCHES "^((tests/)?proofs|bench)/")
          set(allowed TRUE)
        endif()
      elseif(line MATCHES "rapidcheck")
        if(rel MATCHES "^tests/")
          set(allowed TRUE)
        endif()
      elseif(line MATCHES "CLI/")
        if(rel MATCHES "^(cli/command_line.cpp|tests/)")
          set(allowed TRUE)
        endif()
      elseif(line MATCHES "nlohmann/json.hpp")
        if((private OR rel STREQUAL "reports/json_document.hpp") AND NOT rel MATCHES "^cli/")
          set(allowed TRUE)
        endif()
      elseif(private AND NOT rel MATCHES "^cli/")  # reports/json_document.hpp
        set(allowed TRUE)
      endif()
      if(NOT allowed)
        message(SEND_ERROR "${rel}: ${line} outside the files allowed to see it")
        math(EXPR errors "${errors} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()

# A folder's detail/ headers are its own (issue 63): only the folder's
# files, its own tests (tests/<folder>/) and the fuzz harnesses (fuzz/,
# which exercise internals as tests do) include them. rewriting/'s scheme,
# DPO and embedded rewriters sit there, behind the Applier; proofs/' Z3
# encodings, io/'s yaml-cpp readers and campaign/'s shard records too.
foreach(layer IN LISTS known)
  file(GLOB_RECURSE sources "${ROOT}/${layer}/*.hpp" "${ROOT}/${layer}/*.cpp")
  foreach(source IN LISTS sources)
    file(RELATIVE_PATH rel "${ROOT}" "${source}")
    file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/detail/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z_]+)/detail/.*" "\\1" owner "${line}")
      if(NOT rel MATCHES "^(tests/)?${owner}/" AND NOT rel MATCHES "^fuzz/")
        message(SEND_ERROR "${rel}: ${line}: a detail/ header of ${owner}/, which only ${owner}/, tests/${owner}/ and fuzz/ include")
        math(EXPR errors "${errors} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()

if(errors GREATER 0)
  message(FATAL_ERROR "${errors} upward, heavy or detail include(s)")
endif()
message(STATUS "layering: ${checked} files, no upward include, heavy headers in place, detail/ headers at home")
