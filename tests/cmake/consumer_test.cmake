# Tests of the installed CMake package, run by ctest as `cmake -P`:
#
#   MODE=install     install the build into PREFIX (a fresh folder)
#   MODE=exr         build examples/consumer against PREFIX with the OpenEXR
#                    table only, run it and check the value it prints
#   MODE=cpp         the same with the C++ header table; prints "SKIPPED"
#                    when the installed tool has no --format option
#   MODE=regenerate  the tables are generated on the first build, not on a
#                    second, again after an option changes and after the
#                    tool changes
#
# Other variables: BUILD_DIR (the brdflut build), PREFIX, SOURCE_DIR (the
# consumer's sources), WORK_DIR (its build folder), GENERATOR,
# MAKE_PROGRAM, CXX_COMPILER, CONFIG, LINKER_FLAGS.
cmake_minimum_required(VERSION 3.22)

# E_avg(alpha = 1) of GGX = (4/3)(1 - ln 2) = 0.40913709259; stored as
# float, so 6 digits are exact.
set(expected_e_avg "0\\.409137")
set(generation_comment "brdflut: generating")

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    list(JOIN ARGV " " command)
    message(FATAL_ERROR "failed (${status}): ${command}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

function(configure_consumer)
  set(args -S "${SOURCE_DIR}" -B "${WORK_DIR}" -G "${GENERATOR}" "-DCMAKE_PREFIX_PATH=${PREFIX}"
      "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
  if(MAKE_PROGRAM)
    list(APPEND args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
  endif()
  if(CONFIG)
    list(APPEND args "-DCMAKE_BUILD_TYPE=${CONFIG}")
  endif()
  if(LINKER_FLAGS)
    list(APPEND args "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
  endif()
  run("${CMAKE_COMMAND}" ${args} ${ARGV})
endfunction()

# Builds the consumer; sets `generations` to how many times the tables were
# generated.
function(build_consumer)
  set(args --build "${WORK_DIR}")
  if(CONFIG)
    list(APPEND args --config "${CONFIG}")
  endif()
  run("${CMAKE_COMMAND}" ${args})
  string(REGEX MATCHALL "${generation_comment}" hits "${out}")
  list(LENGTH hits count)
  set(generations ${count} PARENT_SCOPE)
endfunction()

function(expect_generations expected what)
  build_consumer()
  if(NOT generations EQUAL expected)
    message(FATAL_ERROR "${what}: the tables were generated ${generations} time(s), expected ${expected}")
  endif()
  message(STATUS "${what}: generated ${generations} time(s), as expected")
endfunction()

function(run_consumer)
  set(exe "${WORK_DIR}/consumer")
  if(NOT EXISTS "${exe}" AND CONFIG)
    set(exe "${WORK_DIR}/${CONFIG}/consumer")
  endif()
  run("${exe}")
  message(STATUS "consumer printed:\n${out}")
  set(out "${out}" PARENT_SCOPE)
endfunction()

function(expect_line regex)
  if(NOT out MATCHES "${regex}")
    message(FATAL_ERROR "the consumer's output has no line matching '${regex}':\n${out}")
  endif()
endfunction()

if(MODE STREQUAL "install")
  file(REMOVE_RECURSE "${PREFIX}")
  set(args --install "${BUILD_DIR}" --prefix "${PREFIX}")
  if(CONFIG)
    list(APPEND args --config "${CONFIG}")
  endif()
  run("${CMAKE_COMMAND}" ${args})
  foreach(file bin/brdflut include/brdflut/catalogue.h)
    if(NOT EXISTS "${PREFIX}/${file}")
      message(FATAL_ERROR "not installed: ${PREFIX}/${file}")
    endif()
  endforeach()

elseif(MODE STREQUAL "exr")
  file(REMOVE_RECURSE "${WORK_DIR}")
  configure_consumer(-DCONSUMER_CPP_HEADER=OFF)
  expect_generations(1 "first build")
  run_consumer()
  expect_line("table: ggx_albedo_avg: GGX average albedo")
  expect_line("exr E_avg\\(alpha = 1\\) = ${expected_e_avg}[0-9]* \\(32 texels, endpoints\\)")
  # SHADER glsl hlsl: the lookup functions beside the table.
  foreach(language glsl hlsl)
    set(shader "${WORK_DIR}/exr/ggx_albedo_avg.${language}")
    if(NOT EXISTS "${shader}")
      message(FATAL_ERROR "brdflut_add_luts(SHADER ${language}) wrote no ${shader}")
    endif()
    file(READ "${shader}" text)
    if(NOT text MATCHES "brdflut_ggx_albedo_avg_value brdflut_ggx_albedo_avg\\(")
      message(FATAL_ERROR "${shader} has no function brdflut_ggx_albedo_avg:\n${text}")
    endif()
  endforeach()

elseif(MODE STREQUAL "cpp")
  execute_process(COMMAND "${PREFIX}/bin/brdflut" generate --help OUTPUT_VARIABLE help)
  if(NOT help MATCHES "--format")
    message("SKIPPED: the installed brdflut has no --format option, so no C++ header table")
    return()
  endif()
  file(REMOVE_RECURSE "${WORK_DIR}")
  configure_consumer(-DCONSUMER_CPP_HEADER=ON)
  expect_generations(2 "first build (header and OpenEXR)")
  # The declared outputs are the files the tool writes: nothing reruns.
  expect_generations(0 "second build")
  run_consumer()
  expect_line("header E_avg\\(alpha = 1\\) = ${expected_e_avg}")
  expect_line("exr E_avg\\(alpha = 1\\) = ${expected_e_avg}")

elseif(MODE STREQUAL "regenerate")
  file(REMOVE_RECURSE "${WORK_DIR}")
  configure_consumer(-DCONSUMER_CPP_HEADER=OFF -DCONSUMER_ALPHA_COUNT=32)
  expect_generations(1 "first build")
  expect_generations(0 "second build, nothing changed")
  configure_consumer(-DCONSUMER_ALPHA_COUNT=32)
  expect_generations(0 "after configuring again with the same settings")
  configure_consumer(-DCONSUMER_ALPHA_COUNT=16)
  expect_generations(1 "after changing --count")
  run_consumer()
  expect_line("exr E_avg\\(alpha = 1\\) = ${expected_e_avg}[0-9]* \\(16 texels, endpoints\\)")
  expect_generations(0 "build after the change")
  file(TOUCH "${PREFIX}/bin/brdflut")
  expect_generations(1 "after the tool changed")
  expect_generations(0 "build after the tool changed")

else()
  message(FATAL_ERROR "MODE must be install, exr, cpp or regenerate, not '${MODE}'")
endif()
