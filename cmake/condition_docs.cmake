# Writes each section of docs/conditions.md (from `<a id="X"></a>` to the
# next anchor or heading of level 2) as a C++ table entry
# {"X", R"dc(...)dc"}, so that SARIF embeds the explanation itself (GitHub
# code scanning shows `help.markdown`; a file:// link is dead on a server).
# cmake -DIN=docs/conditions.md -DOUT=condition_docs.inc -P condition_docs.cmake
file(READ "${IN}" text)
string(REGEX MATCHALL "<a id=\"[a-z-]+\"></a>" anchors "${text}")
set(out "// Generated from docs/conditions.md by cmake/condition_docs.cmake.\n")
foreach(anchor IN LISTS anchors)
  string(REGEX REPLACE "<a id=\"([a-z-]+)\"></a>" "\\1" id "${anchor}")
  string(FIND "${text}" "${anchor}" at)
  string(LENGTH "${anchor}" n)
  math(EXPR at "${at} + ${n} + 1")
  string(SUBSTRING "${text}" ${at} -1 rest)
  # The section ends at the next anchor or level-2 heading.
  string(FIND "${rest}" "\n<a id=" next_anchor)
  string(FIND "${rest}" "\n## " next_heading)
  set(end ${next_anchor})
  if(end EQUAL -1 OR (NOT next_heading EQUAL -1 AND next_heading LESS end))
    set(end ${next_heading})
  endif()
  string(SUBSTRING "${rest}" 0 ${end} section)
  string(STRIP "${section}" section)
  if(section MATCHES "\\)dc\"")
    message(FATAL_ERROR "${IN}: the section ${id} holds the raw string's end )dc\"")
  endif()
  string(APPEND out "{\"${id}\", R\"dc(${section})dc\"},\n")
endforeach()
file(WRITE "${OUT}.new" "${out}")
file(COPY_FILE "${OUT}.new" "${OUT}" ONLY_IF_DIFFERENT)
