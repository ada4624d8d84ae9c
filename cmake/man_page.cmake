# Writes the man page of dartcheck with help2man (cmake -P, from
# cli/CMakeLists.txt): NAME, SYNOPSIS and OPTIONS from `dartcheck --help`,
# then a COMMANDS section with each command's own --help, so the page says
# what the binary says, and the sections of cmake/man_sections.h2m (EXIT
# STATUS, ENVIRONMENT, EXAMPLES, SEE ALSO). -DDARTCHECK=<binary>
# -DOUT=<dartcheck.1> -DINCLUDE=<scratch file for help2man's --include>
# -DSECTIONS=<cmake/man_sections.h2m>.
execute_process(COMMAND "${DARTCHECK}" --help OUTPUT_VARIABLE top RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${DARTCHECK} --help failed (${rc})")
endif()
string(FIND "${top}" "\nSubcommands:\n" at)
string(SUBSTRING "${top}" ${at} -1 subcommands)
string(FIND "${subcommands}" "\n\n" end)  # the options follow the commands
string(SUBSTRING "${subcommands}" 0 ${end} subcommands)
string(REGEX MATCHALL "\n  [a-z][a-z-]*" names "${subcommands}")
set(text "[COMMANDS]\nEach command's options; `dartcheck help COMMAND` prints the same.\n")
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  execute_process(COMMAND "${DARTCHECK}" ${name} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${DARTCHECK} ${name} --help failed (${rc})")
  endif()
  # roff: a backslash is \e; a line may not start with a control character.
  string(REPLACE "\\" "\\e" help "${help}")
  string(REGEX REPLACE "\n([.'])" "\n\\\\&\\1" help "${help}")
  string(APPEND text ".SS ${name}\n.nf\n${help}.fi\n")
endforeach()
# help2man turns every non-ASCII character into "??": the Greek letters of
# the help texts become groff strings, defined after .TH with an ASCII
# fallback for man on an ASCII terminal.
set(definitions "")
function(glyph character name utf8 ascii)
  string(REPLACE "${character}" "\\*[${name}]" replaced "${text}")
  set(text "${replaced}" PARENT_SCOPE)
  set(definitions "${definitions}.ie '\\*(.T'ascii' .ds ${name} ${ascii}\n.el .ds ${name} ${utf8}\n" PARENT_SCOPE)
endfunction()
glyph("ε̄" dc-epsbar "\\[*e]\\[u0304]" "~eps")  # before the plain epsilon it starts with
glyph("ε" dc-eps "\\[*e]" "eps")
glyph("κ" dc-kappa "\\[*k]" "kappa")
glyph("↔" dc-both "\\[<>]" "<->")
file(READ "${SECTIONS}" sections)
file(WRITE "${INCLUDE}" "${text}${sections}")
execute_process(COMMAND help2man --no-info --no-discard-stderr "--name=verifies modeling operations on generalized and oriented maps"
                        "--include=${INCLUDE}" "--output=${OUT}" "${DARTCHECK}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man failed (${rc})")
endif()
file(READ "${OUT}" page)
if(page MATCHES "\\?\\?")
  message(FATAL_ERROR "${OUT}: help2man wrote '??' for a character with no groff string here: add a glyph() line")
endif()
string(FIND "${page}" "\n.SH" at)
math(EXPR at "${at} + 1")
string(SUBSTRING "${page}" 0 ${at} head)
string(SUBSTRING "${page}" ${at} -1 tail)
file(WRITE "${OUT}" "${head}${definitions}${tail}")
