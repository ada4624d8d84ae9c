# The mutation check of the compiled operations (issue 41): copies IN to
# OUT with the first occurrence of FIND replaced by REPLACE (one link's
# dimension, one weight of a term), a change the differential test must
# notice.
#   cmake -DIN=header -DOUT=mutant "-DFIND=text" "-DREPLACE=text" -P mutate.cmake
file(READ ${IN} text)
string(FIND "${text}" "${FIND}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${IN} has no '${FIND}': nothing to mutate")
endif()
string(SUBSTRING "${text}" 0 ${at} head)
string(LENGTH "${FIND}" length)
math(EXPR rest "${at} + ${length}")
string(SUBSTRING "${text}" ${rest} -1 tail)
file(WRITE ${OUT} "${head}${REPLACE}${tail}")
