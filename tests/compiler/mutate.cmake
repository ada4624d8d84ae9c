# The mutation check of the compiled operations (issue 41): copies IN to
# OUT with the first occurrence of FIND replaced by REPLACE (one link's
# dimension, one weight of a term), a change the differential test must
# notice; with AFTER, the first occurrence after the first AFTER (a
# change in one function).
#   cmake -DIN=header -DOUT=mutant "-DFIND=text" "-DREPLACE=text" ["-DAFTER=text"] -P mutate.cmake
file(READ ${IN} text)
set(skipped "")
if(AFTER)
  string(FIND "${text}" "${AFTER}" start)
  if(start EQUAL -1)
    message(FATAL_ERROR "${IN} has no '${AFTER}'")
  endif()
  string(SUBSTRING "${text}" 0 ${start} skipped)
  string(SUBSTRING "${text}" ${start} -1 text)
endif()
string(FIND "${text}" "${FIND}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${IN} has no '${FIND}': nothing to mutate")
endif()
string(SUBSTRING "${text}" 0 ${at} head)
string(LENGTH "${FIND}" length)
math(EXPR rest "${at} + ${length}")
string(SUBSTRING "${text}" ${rest} -1 tail)
file(WRITE ${OUT} "${skipped}${head}${REPLACE}${tail}")
