# The layering rules of src/, checked on every test run (ctest -R layering):
#   src/optics  includes only optics/ (the optics library has no renderer inside);
#   src/core    includes only core/   (math, rays, spectra and the plugin interfaces);
#   src/render  includes only core/ and render/ (the render loop knows no scene text);
#   src/scene   includes only core/, scene/ and render/: no plugin folder, so adding a
#               plugin never touches them (the plugins are registered in src/builtin_plugins.cpp);
#   src/distributed includes only core/, render/ and distributed/ (MPI beside the render loop);
#   src/oiio    includes only render/ (the OpenImageIO module sees the interface it implements,
#               render/image_library.h, and links nothing of eyetrace).
# Run: cmake -DSRC=<source dir>/src -P check_layers.cmake
cmake_policy(SET CMP0057 NEW)
set(allowed_optics "optics")
set(allowed_core "core")
set(allowed_scene "core;scene;render")
set(allowed_render "core;render")
set(allowed_distributed "core;render;distributed")
set(allowed_oiio "render")
set(violations "")
foreach(layer optics core scene render distributed oiio)
  file(GLOB_RECURSE files "${SRC}/${layer}/*.h" "${SRC}/${layer}/*.cpp")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]+\"")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" target "${line}")
      string(FIND "${target}" "/" slash)
      if(slash EQUAL -1)
        continue()  # a file of the same folder, included by bare name
      endif()
      string(SUBSTRING "${target}" 0 ${slash} folder)
      if(NOT folder IN_LIST allowed_${layer})
        file(RELATIVE_PATH rel "${SRC}" "${file}")
        string(REPLACE ";" ", " allowed "${allowed_${layer}}")
        list(APPEND violations "src/${rel} includes \"${target}\" (src/${layer} may include only: ${allowed})")
      endif()
    endforeach()
  endforeach()
endforeach()
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
message(STATUS "layering: optics, core, scene, render, distributed and oiio include only what they may")
