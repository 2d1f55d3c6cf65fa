# Writes one CTest test per gtest suite of a test program (the sanitizer build's registration,
# tests/CMakeLists.txt): run after the program is built, with
#   -DEXE=<program> -DOUT=<file to write> -DLABELS=<label> -DNAME=<program's target name>
#   -DWORKDIR=<working directory>
# Each suite runs as one process (`--gtest_filter=<suite>.*`), which spares the sanitizer
# runtimes' start and exit per test (docs/robustness.md, "CI"). Test names are
# <target>/<suite>; the list of them is ${NAME}_TESTS, as gtest_discover_tests would set it.
execute_process(COMMAND "${EXE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE rc
                WORKING_DIRECTORY "${WORKDIR}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXE} --gtest_list_tests failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(text "")
set(names "")
foreach(line IN LISTS lines)
  # A suite's line is flush left and ends in "." (a typed or parameterised one has a comment after it).
  if(line MATCHES "^([A-Za-z_][A-Za-z0-9_/]*)\\.( |$)")
    set(suite "${CMAKE_MATCH_1}")
    set(name "${NAME}/${suite}")
    string(APPEND text "add_test(\"${name}\" \"${EXE}\" \"--gtest_filter=${suite}.*\")\n"
                       "set_tests_properties(\"${name}\" PROPERTIES LABELS \"${LABELS}\" WORKING_DIRECTORY \"${WORKDIR}\")\n")
    list(APPEND names "${name}")
  endif()
endforeach()
string(APPEND text "set(${NAME}_TESTS \"${names}\")\n")
file(WRITE "${OUT}" "${text}")
