# Checks that the texture generator reproduces the checked-in PNGs byte for byte.
#
#   cmake -DGENERATOR=<path to hexc-gen-textures> -DSOURCE_DIR=<materials/textures>
#         -DWORK_DIR=<scratch dir> -P check_textures.cmake
#
# Runs the generator into WORK_DIR (emptied first) and compares every PNG it writes with the file of
# the same name in SOURCE_DIR, and checks that SOURCE_DIR holds no PNG the generator does not write.
cmake_minimum_required(VERSION 3.25)  # script mode: sets the policies (IN_LIST) to NEW
foreach(var GENERATOR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "check_textures.cmake: pass -D${var}=...")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(COMMAND "${GENERATOR}" "${WORK_DIR}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_textures.cmake: ${GENERATOR} ${WORK_DIR} failed (${rc})")
endif()

file(GLOB generated RELATIVE "${WORK_DIR}" "${WORK_DIR}/*.png")
file(GLOB checked_in RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*.png")
list(SORT generated)
list(SORT checked_in)
if(NOT generated)
  message(FATAL_ERROR "check_textures.cmake: the generator wrote no PNG into ${WORK_DIR}")
endif()

set(problems "")
foreach(name IN LISTS generated)
  if(NOT EXISTS "${SOURCE_DIR}/${name}")
    string(APPEND problems "\n  ${name}: generated but not checked in")
    continue()
  endif()
  file(SHA256 "${WORK_DIR}/${name}" new_hash)
  file(SHA256 "${SOURCE_DIR}/${name}" old_hash)
  if(NOT new_hash STREQUAL old_hash)
    file(SIZE "${WORK_DIR}/${name}" new_size)
    file(SIZE "${SOURCE_DIR}/${name}" old_size)
    string(APPEND problems "\n  ${name}: differs (generated ${new_size} bytes, sha256 ${new_hash};"
                           " checked in ${old_size} bytes, sha256 ${old_hash})")
  endif()
endforeach()
foreach(name IN LISTS checked_in)
  if(NOT name IN_LIST generated)
    string(APPEND problems "\n  ${name}: checked in but no longer generated")
  endif()
endforeach()

if(problems)
  message(FATAL_ERROR "Generated textures do not match ${SOURCE_DIR}:${problems}\n"
    "If the generator changed on purpose, run `cmake --build <build> --target hexc-regen-textures` and "
    "review the new PNGs. If it did not, the output is no longer deterministic (or libstb's PNG "
    "encoder changed): compare ${WORK_DIR} with the checked-in files.")
endif()
list(LENGTH generated count)
message(STATUS "check_textures: ${count} PNGs identical to ${SOURCE_DIR}")
