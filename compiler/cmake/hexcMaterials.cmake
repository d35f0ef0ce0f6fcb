# hexc_add_materials(<target> MATERIALS <material.json|.mtlx>... OUTPUT_DIR <dir>
#                    [TARGETS spirv|hlsl|glsl|msl ...] [OPTIONS <hexc option>...])
#
# One build rule per material, running hexc::hexc with a depfile, so a change to the material, a texture or a
# template rebuilds that material only. Every output is declared (<dir>/<name>.frag.{spv,hlsl,glsl,metal} for the
# chosen TARGETS, default all four, and <dir>/<name>.manifest.json), so a deleted output is rebuilt and other
# rules can depend on the files. <name> is the material's "name" (each <surfacematerial>'s for a MaterialX
# document, docs/materialx.md); CMake reads it at configure time and re-configures when a material file changes. <target> (ALL) builds them all; its HEXC_OUTPUTS property lists
# the files.
# The materials a file holds: a JSON material's "name", or each <surfacematerial>'s of a MaterialX document.
function(_hexc_material_names file out)
  file(READ ${file} text)
  if(file MATCHES "\\.[mM][tT][lL][xX]$")
    string(REGEX MATCHALL "<surfacematerial[^>]*>" elements "${text}")
    set(names)
    foreach(element IN LISTS elements)
      if(element MATCHES "[ \t\r\n]name=\"([^\"]*)\"")
        list(APPEND names ${CMAKE_MATCH_1})
      endif()
    endforeach()
  else()
    string(JSON names ERROR_VARIABLE error GET "${text}" name)
    if(error)
      message(FATAL_ERROR "hexc_add_materials: ${file} has no material name: ${error}")
    endif()
  endif()
  set(${out} ${names} PARENT_SCOPE)
endfunction()

function(hexc_add_materials target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "OUTPUT_DIR" "MATERIALS;TARGETS;OPTIONS")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_MATERIALS OR NOT arg_OUTPUT_DIR)
    message(FATAL_ERROR "hexc_add_materials(${target} MATERIALS <file>... OUTPUT_DIR <dir> [TARGETS ...] [OPTIONS ...]): "
                        "missing MATERIALS or OUTPUT_DIR, or unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGETS)
    set(arg_TARGETS spirv hlsl glsl msl)
  endif()
  set(extension_spirv spv)
  set(extension_hlsl hlsl)
  set(extension_glsl glsl)
  set(extension_msl metal)
  foreach(t IN LISTS arg_TARGETS)
    if(NOT DEFINED extension_${t})
      message(FATAL_ERROR "hexc_add_materials(${target}): unknown target `${t}`; expected spirv, hlsl, glsl or msl")
    endif()
  endforeach()
  list(JOIN arg_TARGETS "," targets)
  cmake_path(ABSOLUTE_PATH arg_OUTPUT_DIR BASE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} NORMALIZE OUTPUT_VARIABLE out_dir)
  set(all_outputs)
  set(depfile_dir ${CMAKE_CURRENT_BINARY_DIR}/hexc/${target})
  file(MAKE_DIRECTORY ${depfile_dir})
  foreach(material IN LISTS arg_MATERIALS)
    cmake_path(ABSOLUTE_PATH material BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} NORMALIZE OUTPUT_VARIABLE file)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
    _hexc_material_names(${file} names)
    if(NOT names)
      message(FATAL_ERROR "hexc_add_materials(${target}): ${file} names no material")
    endif()
    set(outputs)
    foreach(name IN LISTS names)
      list(APPEND outputs ${out_dir}/${name}.manifest.json)
      foreach(t IN LISTS arg_TARGETS)
        list(APPEND outputs ${out_dir}/${name}.frag.${extension_${t}})
      endforeach()
    endforeach()
    cmake_path(GET file STEM stem)
    set(depfile ${depfile_dir}/${stem}.d)
    list(JOIN names " " comment)
    add_custom_command(OUTPUT ${outputs}
      COMMAND hexc::hexc ${file} -o ${out_dir} --targets ${targets} --depfile ${depfile} -q ${arg_OPTIONS}
      DEPENDS ${file} hexc::hexc
      DEPFILE ${depfile}
      COMMENT "hexc: compiling ${comment}"
      VERBATIM)
    list(APPEND all_outputs ${outputs})
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${all_outputs})
  set_property(TARGET ${target} PROPERTY HEXC_OUTPUTS ${all_outputs})
endfunction()
