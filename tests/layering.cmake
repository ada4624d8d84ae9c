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

# Heavy headers stay where they are needed (issue 36): yaml-cpp only in io's
# .cpp files (and io's own private yaml_*.hpp, which only those and the io
# tests include), z3++.h only in proofs/ and its tests and benchmarks (its
# public headers are plain result types), RapidCheck only in tests/, CLI11
# only in cli/command_line.cpp, and no header of the whole JSON library in
# cli/ (the commands state their parameters as campaign::Parameters and
# leave JSON to reports/ and campaign/; json_fwd.hpp declares the type).
set(heavy_headers "yaml-cpp/|io/yaml_util.hpp|io/yaml_readers.hpp|z3\\+\\+.h|proofs/host_encoding.hpp|proofs/dpo_encoding.hpp|proofs/scheme_encoding.hpp|rapidcheck|CLI/|nlohmann/json.hpp|reports/json_document.hpp|campaign/shard_stream.hpp|campaign/result_record.hpp")
foreach(layer IN LISTS known)
  file(GLOB_RECURSE sources "${ROOT}/${layer}/*.hpp" "${ROOT}/${layer}/*.cpp")
  foreach(source IN LISTS sources)
    file(RELATIVE_PATH rel "${ROOT}" "${source}")
    file(STRINGS "${source}" includes REGEX "^#include [<\"](${heavy_headers})")
    foreach(line IN LISTS includes)
      set(allowed FALSE)
      if(line MATCHES "yaml" AND (rel MATCHES "^io/.*\\.cpp$" OR rel MATCHES "^io/yaml_(util|readers)\\.hpp$" OR rel MATCHES "^tests/io/"
                                  OR rel MATCHES "^tests/analysis/test_fuzz.cpp$"))
        set(allowed TRUE)
      elseif(line MATCHES "z3|proofs/" AND rel MATCHES "^(proofs|tests/proofs|bench)/")
        set(allowed TRUE)
      elseif(line MATCHES "rapidcheck" AND rel MATCHES "^tests/")
        set(allowed TRUE)
      elseif(line MATCHES "CLI/" AND rel MATCHES "^(cli/command_line.cpp|tests/)")
        set(allowed TRUE)
      elseif(line MATCHES "json|shard_stream|result_record" AND NOT rel MATCHES "^cli/")
        set(allowed TRUE)
      endif()
      if(NOT allowed)
        message(SEND_ERROR "${rel}: ${line} outside the files allowed to see it")
        math(EXPR errors "${errors} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()

if(errors GREATER 0)
  message(FATAL_ERROR "${errors} upward or heavy include(s)")
endif()
message(STATUS "layering: ${checked} files, no upward include, heavy headers in place")
