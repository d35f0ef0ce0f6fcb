# hexc_embed(OUT FUNCTION HEADER FILES...): writes OUT, a C++ source defining
#   const std::map<std::string, std::string>& FUNCTION()   // file name -> contents
# declared in HEADER, so a binary carries its shaders. Deterministic: keyed by file name only.
set(HEXC_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake)
function(hexc_embed out function header)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DFUNCTION=${function} -DHEADER=${header} "-DFILES=${ARGN}" -P ${HEXC_EMBED_SCRIPT}
    DEPENDS ${ARGN} ${HEXC_EMBED_SCRIPT}
    COMMENT "Embedding ${function}"
    VERBATIM)
endfunction()

# hexc_concat(OUT FILES...): writes OUT, the FILES in order with an empty line between two: one include file made of
# several (templates/library/hextiling/), whose `#line` numbers count in OUT.
set(HEXC_CONCAT_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/concat_files.cmake)
function(hexc_concat out)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} "-DFILES=${ARGN}" -P ${HEXC_CONCAT_SCRIPT}
    DEPENDS ${ARGN} ${HEXC_CONCAT_SCRIPT}
    COMMENT "Assembling ${out}"
    VERBATIM)
endfunction()
