# The mutation check of the compiled operations (issue 41): copies IN to
# OUT with the first added 0-arc of the first rule that adds one turned into
# a 1-arc, a change that the differential test must notice.
#   cmake -DIN=header -DOUT=mutant -P mutate.cmake
file(READ ${IN} text)
string(FIND "${text}" "    g.set_link(0, comatch[" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${IN} adds no 0-arc: nothing to mutate")
endif()
string(SUBSTRING "${text}" 0 ${at} head)
math(EXPR rest "${at} + 17")
string(SUBSTRING "${text}" ${rest} -1 tail)
file(WRITE ${OUT} "${head}    g.set_link(1,${tail}")
