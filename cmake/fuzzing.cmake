# libFuzzer support (EYETRACE_FUZZ): coverage-guided fuzz targets built with clang's
# -fsanitize=fuzzer plus AddressSanitizer and UndefinedBehaviorSanitizer, so that a crash, a
# hang, a leak or any undefined behaviour stops the run with the input that caused it.
#
# Use a build directory of its own (tools/fuzz does): the code under test is compiled with
# coverage instrumentation, which is no use in a normal build.
include_guard(GLOBAL)

set(EYETRACE_FUZZ_SUPPORTED OFF)
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  set(EYETRACE_FUZZ_SUPPORTED ON)
else()
  message(WARNING "EYETRACE_FUZZ needs clang (libFuzzer); ${CMAKE_CXX_COMPILER_ID} cannot build "
                  "the fuzz targets. Configure with -DCMAKE_CXX_COMPILER=clang++ (see tools/fuzz).")
endif()

# UBSan findings must stop the run (not just print), or libFuzzer would not keep the input.
set(EYETRACE_FUZZ_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all
    -fno-omit-frame-pointer)

# clang 14 miscompiles fmt's consteval format-string check in some switch statements: the
# temporary SourceLoc of `case A: fail(loc(), "..."); case B: fail(loc(), "...");` is freed
# although it was never constructed (free(): invalid pointer; reproduced without sanitizers,
# fixed in clang 15). Checking format strings at run time instead avoids it; gcc builds keep
# the compile-time check.
set(EYETRACE_FUZZ_DEFINITIONS "")
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 15)
  set(EYETRACE_FUZZ_DEFINITIONS FMT_CONSTEVAL=)
endif()

# Instruments a library the fuzz targets exercise: coverage for the fuzzer, sanitizers for
# the findings. Anything linking it must link the sanitizer runtimes too.
function(eyetrace_fuzz_instrument target)
  target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link ${EYETRACE_FUZZ_SANITIZERS})
  target_compile_definitions(${target} PUBLIC ${EYETRACE_FUZZ_DEFINITIONS})
  target_link_options(${target} INTERFACE -fsanitize=address,undefined)
endfunction()

# eyetrace_add_fuzzer(<name> SOURCES <files...> LIBRARIES <targets...>)
# builds <name> with libFuzzer's main into <build>/fuzz/<name>.
function(eyetrace_add_fuzzer name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE -fsanitize=fuzzer ${EYETRACE_FUZZ_SANITIZERS})
  target_link_options(${name} PRIVATE -fsanitize=fuzzer ${EYETRACE_FUZZ_SANITIZERS})
  target_compile_definitions(${name} PRIVATE ${EYETRACE_FUZZ_DEFINITIONS})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fuzz)
  set_property(GLOBAL APPEND PROPERTY EYETRACE_FUZZERS ${name})
endfunction()
