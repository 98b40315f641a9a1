# Embeds files in the program as C++ byte arrays, so that an executable carries them without a tool beyond
# CMake. glossy_embed_files(TARGET NAMESPACE OUTPUT FILE=function ...) adds OUTPUT (a .cpp in the build
# tree, made again whenever a file changes) to TARGET; it defines `std::string_view function()` in
# NAMESPACE for each FILE, which a header of the target declares. Run as a script (cmake -P) it writes that
# .cpp; the variables say what to write.

if(CMAKE_SCRIPT_MODE_FILE)
  set(_out "// Made by cmake/embed_files.cmake from ${SOURCE_DIR}: edit those files, not this one.\n#include <string_view>\n\nnamespace ${NAMESPACE} {\n")
  string(REPLACE "," ";" _entries "${ENTRIES}")
  foreach(_entry IN LISTS _entries)
    string(REPLACE "=" ";" _pair "${_entry}")
    list(GET _pair 0 _file)
    list(GET _pair 1 _function)
    file(READ "${SOURCE_DIR}/${_file}" _hex HEX)
    string(LENGTH "${_hex}" _length)
    math(EXPR _bytes "${_length} / 2")
    string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," _chars "${_hex}")
    string(APPEND _out "\nstd::string_view ${_function}() {\n  static constexpr char kBytes[] = {\n    ${_chars}0};\n"
                       "  return {kBytes, ${_bytes}};\n}\n")
  endforeach()
  string(APPEND _out "\n}  // namespace ${NAMESPACE}\n")
  file(WRITE "${OUTPUT}.tmp" "${_out}")
  file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
  return()
endif()

set(_glossy_embed_script ${CMAKE_CURRENT_LIST_FILE})

function(glossy_embed_files target namespace output)
  set(_depends)
  foreach(_entry IN LISTS ARGN)
    string(REPLACE "=" ";" _pair "${_entry}")
    list(GET _pair 0 _file)
    list(APPEND _depends ${CMAKE_CURRENT_SOURCE_DIR}/${_file})
  endforeach()
  string(REPLACE ";" "," _entries "${ARGN}")
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR} -DNAMESPACE=${namespace} -DOUTPUT=${output}
            "-DENTRIES=${_entries}" -P ${_glossy_embed_script}
    DEPENDS ${_depends} ${_glossy_embed_script}
    COMMENT "Embedding ${ARGN}"
    VERBATIM)
  target_sources(${target} PRIVATE ${output})
endfunction()
