# brdflut_add_luts(): generate lookup tables at build time with the brdflut
# tool and make them available to a target.
#
#   brdflut_add_luts(<target>
#                    [TABLES <id>...]
#                    [PRESET <name>]
#                    [FORMAT exr|cpp|png16|dds|ktx2]
#                    [OUTPUT_DIR <dir>]
#                    [SHADER glsl|hlsl...]
#                    [OPTIONS <generate argument>...])
#
# Runs `brdflut generate <ids> [--preset <name>] [--format <format>]
# <options> -q -o <dir>` through a custom command that <target> depends on,
# and adds <dir> to <target>'s include path (PRIVATE), so a `cpp` table is
# included as "<id>.h".
#
#   TABLES      table ids (see `brdflut list`); required unless PRESET is given.
#   PRESET      an engine's convention (`brdflut generate --preset`).
#   FORMAT      exr (default, the tool's own default, so no --format is
#               passed), cpp, png16, dds or ktx2. Each table <id> is written
#               as <dir>/<id>.exr, .h, .png, .dds or .ktx2.
#   OUTPUT_DIR  where the tables go; relative to the current binary folder.
#               Default: ${CMAKE_CURRENT_BINARY_DIR}/brdflut_luts/<target>
#               (<target>_<n> for the n-th call on the same target).
#   SHADER      also write each table's lookup function beside it,
#               <dir>/<id>.glsl and/or <dir>/<id>.hlsl (`--shader`).
#   OPTIONS     further arguments of `brdflut generate`, passed verbatim,
#               e.g. OPTIONS --size 64 --pixel half --placement alpha=endpoints
#
# The custom command depends on the tool's executable and on a settings file
# holding the full command line, which is rewritten only when its content
# changes: the tables are regenerated when the tool or any setting changes,
# and at no other time.
#
# With PRESET the tool decides the file names, so the custom command's
# declared output is a stamp file (<binary dir>/brdflut_luts/<name>.stamp)
# and the tables are whatever the preset writes into OUTPUT_DIR. The target
# is built after them; sources that include them are recompiled through the
# compiler's header dependencies as usual.
#
# The tool is the imported target brdflut::brdflut_cli (from
# find_package(brdflut)) or, inside the brdflut build, its alias.

include_guard(GLOBAL)

function(brdflut_add_luts target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PRESET;FORMAT;OUTPUT_DIR" "TABLES;SHADER;OPTIONS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "brdflut_add_luts: unknown arguments: ${arg_UNPARSED_ARGUMENTS}; "
                        "allowed: TABLES, PRESET, FORMAT, OUTPUT_DIR, SHADER, OPTIONS")
  endif()
  if(NOT TARGET ${target})
    message(FATAL_ERROR "brdflut_add_luts: '${target}' is not a target")
  endif()
  if(NOT TARGET brdflut::brdflut_cli)
    message(FATAL_ERROR "brdflut_add_luts: the brdflut tool (target brdflut::brdflut_cli) "
                        "is not known; call find_package(brdflut CONFIG REQUIRED) first")
  endif()
  if(arg_KEYWORDS_MISSING_VALUES)
    message(FATAL_ERROR "brdflut_add_luts: ${arg_KEYWORDS_MISSING_VALUES} given without a value")
  endif()
  if(NOT arg_TABLES AND NOT DEFINED arg_PRESET)
    message(FATAL_ERROR "brdflut_add_luts: give TABLES <id>... or PRESET <name>")
  endif()

  # Output file of each table, by format.
  set(extension_exr ".exr")
  set(extension_cpp ".h")
  set(extension_png16 ".png")
  set(extension_dds ".dds")
  set(extension_ktx2 ".ktx2")
  if(NOT DEFINED arg_FORMAT)
    set(arg_FORMAT exr)
  endif()
  if(NOT DEFINED extension_${arg_FORMAT})
    message(FATAL_ERROR "brdflut_add_luts: FORMAT '${arg_FORMAT}' is not known; "
                        "allowed: exr, cpp, png16, dds, ktx2")
  endif()

  foreach(language IN LISTS arg_SHADER)
    if(NOT language MATCHES "^(glsl|hlsl)$")
      message(FATAL_ERROR "brdflut_add_luts: SHADER '${language}' is not known; allowed: glsl, hlsl")
    endif()
  endforeach()

  # One name per call, for the helper target and the bookkeeping files.
  get_target_property(calls ${target} BRDFLUT_LUTS_CALLS)
  if(NOT calls)
    set(calls 0)
  endif()
  math(EXPR calls "${calls} + 1")
  set_property(TARGET ${target} PROPERTY BRDFLUT_LUTS_CALLS ${calls})
  if(calls EQUAL 1)
    set(name ${target})
  else()
    set(name ${target}_${calls})
  endif()

  if(NOT DEFINED arg_OUTPUT_DIR)
    set(arg_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/brdflut_luts/${name}")
  endif()
  cmake_path(ABSOLUTE_PATH arg_OUTPUT_DIR BASE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}"
             NORMALIZE OUTPUT_VARIABLE output_dir)

  set(arguments generate ${arg_TABLES})
  if(DEFINED arg_PRESET)
    list(APPEND arguments --preset ${arg_PRESET})
  endif()
  if(NOT arg_FORMAT STREQUAL "exr")
    list(APPEND arguments --format ${arg_FORMAT})
  endif()
  foreach(language IN LISTS arg_SHADER)
    list(APPEND arguments --shader ${language})
  endforeach()
  list(APPEND arguments ${arg_OPTIONS} --quiet -o "${output_dir}")

  set(work_dir "${CMAKE_CURRENT_BINARY_DIR}/brdflut_luts")
  if(DEFINED arg_PRESET)
    set(stamp "${work_dir}/${name}.stamp")
    set(outputs "${stamp}")
    set(touch_stamp COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}")
  else()
    set(outputs "")
    foreach(id IN LISTS arg_TABLES)
      list(APPEND outputs "${output_dir}/${id}${extension_${arg_FORMAT}}")
      foreach(language IN LISTS arg_SHADER)
        list(APPEND outputs "${output_dir}/${id}.${language}")
      endforeach()
    endforeach()
    set(touch_stamp "")
  endif()

  # The settings file: the tool and its full command line. file(GENERATE)
  # rewrites it only when its content changes, so its time stamp moves only
  # when a setting does. Multi-config generators get one per configuration.
  get_property(multi_config GLOBAL PROPERTY GENERATOR_IS_MULTI_CONFIG)
  if(multi_config)
    set(settings "${work_dir}/${name}.settings-$<CONFIG>.txt")
  else()
    set(settings "${work_dir}/${name}.settings.txt")
  endif()
  list(JOIN arguments "\n" arguments_lines)
  file(GENERATE OUTPUT "${settings}"
       CONTENT "$<TARGET_FILE:brdflut::brdflut_cli>\n${arguments_lines}\n")

  list(JOIN arg_TABLES " " what)
  if(DEFINED arg_PRESET)
    string(PREPEND what "preset ${arg_PRESET} ")
  endif()
  if(NOT DEFINED arg_PRESET OR NOT arg_FORMAT STREQUAL "exr")
    string(APPEND what " as ${arg_FORMAT}")
  endif()
  string(STRIP "${what}" what)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND brdflut::brdflut_cli ${arguments}
    ${touch_stamp}
    DEPENDS brdflut::brdflut_cli "$<TARGET_FILE:brdflut::brdflut_cli>" "${settings}"
    COMMENT "brdflut: generating ${what} in ${output_dir}"
    VERBATIM)
  add_custom_target(${name}_brdflut_luts DEPENDS ${outputs})
  add_dependencies(${target} ${name}_brdflut_luts)
  target_include_directories(${target} PRIVATE "${output_dir}")
endfunction()
