# The commit glossy is built from, for what its outputs record of their provenance (a study's results.json,
# `glossy --version`): `git describe --always --dirty` of the source tree, "unknown" outside git or without
# it. Run as a script (cmake -P) at every build, so that a new commit or an edit is seen without
# reconfiguring; it rewrites OUTPUT only when the text changes, so an unchanged tree rebuilds nothing and
# identical trees give identical builds (no date, no host, no path).

if(CMAKE_SCRIPT_MODE_FILE)
  set(_commit "unknown")
  find_package(Git QUIET)
  if(GIT_FOUND)
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                    OUTPUT_VARIABLE _described OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _status)
    if(_status EQUAL 0 AND _described MATCHES "^[0-9A-Za-z._+-]+$")
      set(_commit "${_described}")
    endif()
  endif()
  set(_text "// Made by cmake/build_commit.cmake: the commit of the source tree this build is of.\n#pragma once\n#define GLOSSY_COMMIT \"${_commit}\"\n")
  set(_old "")
  if(EXISTS "${OUTPUT}")
    file(READ "${OUTPUT}" _old)
  endif()
  if(NOT _old STREQUAL _text)
    file(WRITE "${OUTPUT}.tmp" "${_text}")
    file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
  endif()
  return()
endif()

set(_glossy_commit_script ${CMAKE_CURRENT_LIST_FILE})

# Gives TARGET the header OUTPUT_DIR/renderer/util/glossy_commit.h (GLOSSY_COMMIT), checked at every build:
# included by its path from the top, as every glossy header is.
function(glossy_commit_header target output_dir)
  set(_header ${output_dir}/renderer/util/glossy_commit.h)
  add_custom_target(${target}_commit
                    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${_header} -P ${_glossy_commit_script}
                    BYPRODUCTS ${_header}
                    COMMENT "Checking the source tree's commit"
                    VERBATIM)
  add_dependencies(${target} ${target}_commit)
  target_include_directories(${target} PRIVATE ${output_dir})
endfunction()
