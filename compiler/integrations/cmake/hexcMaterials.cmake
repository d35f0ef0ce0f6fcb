# hexc_add_materials(<target> MATERIALS <material.json|.mtlx|scene.json>... OUTPUT_DIR <dir>
#                    [TARGETS <hexc target>...] [OPTIONS <hexc option>...])
#
# One build rule per file, running hexc::hexc with a depfile, so a change to the material, a texture or a template
# rebuilds that file's shaders only. Every output is declared: at configure time `hexc --list-outputs` (with the
# same options) names the files each rule writes (shaders, manifests, histogram tables, packed textures, vertex
# stages, scene variants and index), and CMake configures again when one of the files that list depends on changes
# (the material, a scene, a template, a packing material's textures) or hexc does. So a deleted output is rebuilt,
# other rules can depend on any of them, and no depfile names an undeclared output. <target> (ALL) builds them all;
# its HEXC_OUTPUTS property lists the files. Uses no compiler: works in a project(... LANGUAGES NONE).

# hexc's --targets names, and those it writes when given none (tests/backends/target_table_test.cpp checks both
# against hexc's target table).
set(_HEXC_TARGETS spirv hlsl glsl msl wgsl)
set(_HEXC_DEFAULT_TARGETS spirv hlsl glsl msl)

# The hexc executable of the imported target, to run at configure time.
function(_hexc_executable out)
  get_target_property(configs hexc::hexc IMPORTED_CONFIGURATIONS)
  list(GET configs 0 config)
  get_target_property(exe hexc::hexc IMPORTED_LOCATION_${config})
  set(${out} ${exe} PARENT_SCOPE)
endfunction()

# Fills <outputs> and <inputs> from `hexc <file> <args> --list-outputs`; stops the configure step when the file does
# not plan, after hexc's diagnostics (printed as they are, not re-wrapped by message()).
function(_hexc_list_outputs hexc file args outputs inputs)
  execute_process(COMMAND ${hexc} ${file} ${args} --list-outputs OUTPUT_VARIABLE json RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "hexc_add_materials: hexc cannot list the outputs of ${file} (its diagnostics above)")
  endif()
  foreach(key IN ITEMS outputs inputs)
    set(list)
    string(JSON count LENGTH "${json}" ${key})
    if(count GREATER 0)
      math(EXPR last "${count} - 1")
      foreach(i RANGE ${last})
        string(JSON path GET "${json}" ${key} ${i})
        list(APPEND list ${path})
      endforeach()
    endif()
    set(${${key}} ${list} PARENT_SCOPE)
  endforeach()
endfunction()

function(hexc_add_materials target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "OUTPUT_DIR" "MATERIALS;TARGETS;OPTIONS")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_MATERIALS OR NOT arg_OUTPUT_DIR)
    message(FATAL_ERROR "hexc_add_materials(${target} MATERIALS <file>... OUTPUT_DIR <dir> [TARGETS ...] [OPTIONS ...]): "
                        "missing MATERIALS or OUTPUT_DIR, or unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGETS)
    set(arg_TARGETS ${_HEXC_DEFAULT_TARGETS})
  endif()
  foreach(t IN LISTS arg_TARGETS)
    if(NOT t IN_LIST _HEXC_TARGETS)
      list(JOIN _HEXC_TARGETS ", " known)
      message(FATAL_ERROR "hexc_add_materials(${target}): unknown target `${t}`; expected one of ${known}")
    endif()
  endforeach()
  list(JOIN arg_TARGETS "," targets)
  cmake_path(ABSOLUTE_PATH arg_OUTPUT_DIR BASE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} NORMALIZE OUTPUT_VARIABLE out_dir)
  _hexc_executable(hexc)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${hexc})
  set(all_outputs)
  set(depfile_dir ${CMAKE_CURRENT_BINARY_DIR}/hexc/${target})
  file(MAKE_DIRECTORY ${depfile_dir})
  foreach(material IN LISTS arg_MATERIALS)
    cmake_path(ABSOLUTE_PATH material BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} NORMALIZE OUTPUT_VARIABLE file)
    set(args -o ${out_dir} --targets ${targets} ${arg_OPTIONS})
    _hexc_list_outputs(${hexc} ${file} "${args}" outputs inputs)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file} ${inputs})
    cmake_path(GET file FILENAME name)
    # Named after the outputs: Ninja reads a rule's depfile before it runs the rule, and the one an earlier output set
    # wrote would name an output no longer declared (a removed slot's tables) and stop the build.
    string(MD5 set "${outputs}")
    string(SUBSTRING ${set} 0 12 set)
    set(depfile ${depfile_dir}/${name}.${set}.d)
    file(GLOB earlier ${depfile_dir}/${name}.*.d)
    list(REMOVE_ITEM earlier ${depfile})
    if(earlier)
      file(REMOVE ${earlier})
    endif()
    add_custom_command(OUTPUT ${outputs}
      COMMAND hexc::hexc ${file} ${args} --depfile ${depfile} -q
      DEPENDS ${file} hexc::hexc
      DEPFILE ${depfile}
      COMMENT "hexc: compiling ${name}"
      VERBATIM)
    list(APPEND all_outputs ${outputs})
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${all_outputs})
  set_property(TARGET ${target} PROPERTY HEXC_OUTPUTS ${all_outputs})
endfunction()
