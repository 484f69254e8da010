# The floors check (cmake/check_floors.cmake) on a planted tree: core including app, physics
# linking check (a floor above it), physics including a header core keeps to itself, and a public
# header that does not exist must each be named; a clean tree must pass.
# Run: cmake -DCHECK=<cmake/check_floors.cmake> -DWORK=<scratch dir> -P floors_catch.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/src/core" "${WORK}/src/physics" "${WORK}/src/check")
file(WRITE "${WORK}/src/core/a.cpp" "#include \"core/a.hpp\"\n")
file(WRITE "${WORK}/src/core/a.hpp" "#pragma once\n")
file(WRITE "${WORK}/src/physics/b.cpp" "#include \"core/a.hpp\"\n")
file(WRITE "${WORK}/src/check/c.cpp" "#include \"physics/b.hpp\"\n")
file(WRITE "${WORK}/src/physics/b.hpp" "#pragma once\n")
file(WRITE "${WORK}/src/core/own.hpp" "#pragma once\n")

function(run_check links expect_failure expect_text)
  file(WRITE "${WORK}/links.cmake" "set(FLOORS core physics check app)\nset(SOURCE_DIR \"${WORK}/src\")\nset(EVERY_HEADER ON)\n${links}")
  execute_process(COMMAND ${CMAKE_COMMAND} -DLINKS_FILE=${WORK}/links.cmake -P ${CHECK}
                  RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect_failure AND NOT failed)
    message(FATAL_ERROR "the floors check passed a planted offence (${expect_text})")
  endif()
  if(NOT expect_failure AND failed)
    message(FATAL_ERROR "the floors check refused a clean tree:\n${err}")
  endif()
  if(expect_text AND NOT err MATCHES "${expect_text}")
    message(FATAL_ERROR "the floors check did not name '${expect_text}':\n${err}")
  endif()
endfunction()

set(clean "set(LINKS_core )\nset(FILES_core \"${WORK}/src/core/a.cpp\")\nset(PUBLIC_core a.hpp)\nset(PUBLIC_physics b.hpp)\nset(LINKS_physics core)\nset(FILES_physics \"${WORK}/src/physics/b.cpp\")\nset(LINKS_check physics core)\nset(FILES_check \"${WORK}/src/check/c.cpp\")\n")
run_check("${clean}" OFF "")
# check includes physics but links only core.
string(REPLACE "set(LINKS_check physics core)" "set(LINKS_check core)" unlinked "${clean}")
run_check("${unlinked}" ON "src/check/c.cpp: #include \"physics/b.hpp\", but nbscope_check links only: core")
# physics links check, a floor above it.
string(REPLACE "set(LINKS_physics core)" "set(LINKS_physics core check)" back_arrow "${clean}")
run_check("${back_arrow}" ON "nbscope_physics links nbscope_check, a floor above it")
# physics includes core's own header (not public).
file(WRITE "${WORK}/src/physics/b.cpp" "#include \"core/own.hpp\"\n")
run_check("${clean}" ON "src/physics/b.cpp: #include \"core/own.hpp\", but own.hpp is core's own")
file(WRITE "${WORK}/src/physics/b.cpp" "#include \"core/a.hpp\"\n")
# A public header listed that is not there.
string(REPLACE "set(PUBLIC_physics b.hpp)" "set(PUBLIC_physics b.hpp gone.hpp)" missing "${clean}")
run_check("${missing}" ON "public header gone.hpp is not in src/physics")
# A header of core, included by core's source, includes app.
file(WRITE "${WORK}/src/core/a.hpp" "#pragma once\n#include \"app/x.hpp\"\n")
run_check("${clean}" ON "src/core/a.hpp: #include \"app/x.hpp\", but nbscope_core links only: no other floor")
message(STATUS "the floors check names each planted offence")
