# Installs the library's headers under HP_INCLUDE_DEST (= PREFIX/include/hairpipe) with the project's
# include paths rewritten to that layout, so an application includes <hairpipe/renderer.h> and no
# hairpipe header reaches for "engine/..." (which could be the application's own folder).
# The tools (samples/tools) are not part of the library and not installed.
file(GLOB_RECURSE engine_headers RELATIVE ${HP_SOURCE_DIR}/engine ${HP_SOURCE_DIR}/engine/*.h)
file(GLOB_RECURSE compute_headers RELATIVE ${HP_SOURCE_DIR} ${HP_SOURCE_DIR}/compute/*.h)
file(GLOB_RECURSE shader_headers RELATIVE ${HP_SOURCE_DIR} ${HP_SOURCE_DIR}/shaders/*.h)

function(hp_install_header source destination)
  file(READ ${source} text)
  string(REGEX REPLACE "#include \"engine/" "#include \"hairpipe/" text "${text}")
  string(REGEX REPLACE "#include \"(compute|shaders)/" "#include \"hairpipe/\\1/" text "${text}")
  set(target ${HP_INCLUDE_DEST}/${destination})
  if(EXISTS ${target})
    file(READ ${target} old)
    if(old STREQUAL text)
      message(STATUS "Up-to-date: ${target}")
      return()
    endif()
  endif()
  message(STATUS "Installing: ${target}")
  file(WRITE ${target} "${text}")
endfunction()

foreach(h ${engine_headers})
  hp_install_header(${HP_SOURCE_DIR}/engine/${h} ${h})
endforeach()
foreach(h ${compute_headers} ${shader_headers})
  hp_install_header(${HP_SOURCE_DIR}/${h} ${h})
endforeach()
