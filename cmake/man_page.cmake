# Writes the man page of dartcheck with help2man (cmake -P, from
# cli/CMakeLists.txt): NAME, SYNOPSIS and OPTIONS from `dartcheck --help`,
# then a COMMANDS section with each command's own --help, so the page says
# what the binary says. -DDARTCHECK=<binary> -DOUT=<dartcheck.1>
# -DINCLUDE=<scratch file for help2man's --include>.
execute_process(COMMAND "${DARTCHECK}" --help OUTPUT_VARIABLE top RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${DARTCHECK} --help failed (${rc})")
endif()
string(FIND "${top}" "\nSubcommands:\n" at)
string(SUBSTRING "${top}" ${at} -1 subcommands)
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
file(WRITE "${INCLUDE}" "${text}")
execute_process(COMMAND help2man --no-info --no-discard-stderr "--name=verifies modeling operations on generalized and oriented maps"
                        "--include=${INCLUDE}" "--output=${OUT}" "${DARTCHECK}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man failed (${rc})")
endif()
