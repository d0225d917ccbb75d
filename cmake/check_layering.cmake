# The layering check (docs/design.md §6): a module under src/tailor/ may include only
# itself and the modules to its left in the layer order
#   geometry → mesh → io → bvh → culling → candidates → ccd → detection | scene → sim → …
# (TAILOR_CORE_MODULES then TAILOR_SIM_MODULES in CMakeLists.txt, so a module added there
# takes its place in the order). Every folder under src/tailor/ must be in the order, and
# no file may reach another module by a relative path ("../").
#
# The front door (src/tailor/tailor.hpp, and any file directly under src/tailor/) sits above
# the core library: it may include the modules up to FRONT_DOOR (the last core module,
# detection), never the simulation's, and no module may include it (it is for programs
# using the library; inside, each file includes the headers it uses).
#
#   cmake -DSOURCE_DIR=<checkout> -DLAYERS=geometry,mesh,... -DFRONT_DOOR=detection
#         -P cmake/check_layering.cmake
#   cmake -DSELF_TEST=ON -DWORK_DIR=<scratch> -P cmake/check_layering.cmake
#
# SELF_TEST writes a small tree with one violation of each kind under WORK_DIR and expects
# the check to report each one (so the check itself cannot silently pass everything).
cmake_minimum_required(VERSION 3.25)

# Appends to `out_var` one line per violation found under `source_dir`/src/tailor.
function(tailor_layering_violations source_dir layers front_door out_var)
  set(violations)
  set(root "${source_dir}/src/tailor")
  list(FIND layers ${front_door} front_rank)
  if(front_rank EQUAL -1)
    list(APPEND violations "FRONT_DOOR '${front_door}' is not in the layer order")
  endif()

  # The front door: files directly under src/tailor/.
  file(GLOB doors RELATIVE "${source_dir}" "${root}/*.hpp" "${root}/*.cpp")
  list(SORT doors)
  foreach(file ${doors})
    file(STRINGS "${source_dir}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line ${lines})
      if(line MATCHES "include[ \t]*[\"<]tailor/([A-Za-z0-9_]+)/")
        set(target ${CMAKE_MATCH_1})
        list(FIND layers ${target} target_rank)
        if(target_rank EQUAL -1)
          list(APPEND violations "${file}: includes unknown module '${target}': ${line}")
        elseif(target_rank GREATER front_rank)
          list(APPEND violations
               "${file}: the front door includes ${target}, beyond the core library (up to ${front_door}): ${line}")
        endif()
      endif()
    endforeach()
  endforeach()
  file(GLOB entries LIST_DIRECTORIES true RELATIVE "${root}" "${root}/*")
  foreach(entry ${entries})
    if(IS_DIRECTORY "${root}/${entry}" AND NOT entry IN_LIST layers)
      list(APPEND violations
           "src/tailor/${entry}/ is not in the layer order (add it to TAILOR_CORE_MODULES or TAILOR_SIM_MODULES)")
    endif()
  endforeach()

  foreach(module ${layers})
    list(FIND layers ${module} rank)
    file(GLOB_RECURSE files RELATIVE "${source_dir}" "${root}/${module}/*.hpp" "${root}/${module}/*.cpp")
    list(SORT files)
    foreach(file ${files})
      file(STRINGS "${source_dir}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
      foreach(line ${lines})
        if(line MATCHES "include[ \t]*[\"<]tailor/([A-Za-z0-9_]+)/")
          set(target ${CMAKE_MATCH_1})
          list(FIND layers ${target} target_rank)
          if(target_rank EQUAL -1)
            list(APPEND violations "${file}: includes unknown module '${target}': ${line}")
          elseif(target_rank GREATER rank)
            list(APPEND violations
                 "${file}: ${module} includes ${target}, a module to its right: ${line}")
          endif()
        elseif(line MATCHES "include[ \t]*[\"<]tailor/[A-Za-z0-9_]+\\.[a-z]+[\">]")
          list(APPEND violations "${file}: a module includes the front door: ${line}")
        elseif(line MATCHES "include[ \t]*[\"<][^\">]*\\.\\./")
          list(APPEND violations "${file}: relative include across folders: ${line}")
        endif()
      endforeach()
    endforeach()
  endforeach()
  set(${out_var} "${violations}" PARENT_SCOPE)
endfunction()

function(tailor_layering_write path text)
  get_filename_component(folder "${path}" DIRECTORY)
  file(MAKE_DIRECTORY "${folder}")
  file(WRITE "${path}" "${text}")
endfunction()

if(SELF_TEST)
  set(tree "${WORK_DIR}/layering-self-test")
  file(REMOVE_RECURSE "${tree}")
  set(src "${tree}/src/tailor")
  tailor_layering_write("${src}/geometry/ok.hpp" "#include <vector>\n#include \"tailor/geometry/types.hpp\"\n")
  tailor_layering_write("${src}/geometry/bad.cpp" "  #  include \"tailor/mesh/triangle_mesh.hpp\"\n")
  tailor_layering_write("${src}/mesh/ok.cpp" "#include <tailor/geometry/types.hpp>\n")
  tailor_layering_write("${src}/mesh/sneaky.hpp" "#include \"../sim/cloth_model.hpp\"\n")
  tailor_layering_write("${src}/mesh/unknown.hpp" "#include \"tailor/nowhere/x.hpp\"\n")
  tailor_layering_write("${src}/sim/ok.hpp" "#include \"tailor/mesh/ok.hpp\"\n#include \"tailor/sim/x.hpp\"\n")
  tailor_layering_write("${src}/render/ok.hpp" "#include \"tailor/sim/ok.hpp\"\n")
  tailor_layering_write("${src}/stray/x.hpp" "\n")
  tailor_layering_write("${src}/door.hpp" "#include \"tailor/mesh/ok.cpp\"\n#include \"tailor/sim/ok.hpp\"\n")
  tailor_layering_write("${src}/mesh/inside.cpp" "#include <tailor/door.hpp>\n")
  set(expected
      "src/tailor/stray/ is not in the layer order"
      "src/tailor/geometry/bad.cpp: geometry includes mesh, a module to its right"
      "src/tailor/mesh/sneaky.hpp: relative include across folders"
      "src/tailor/mesh/unknown.hpp: includes unknown module 'nowhere'"
      "src/tailor/door.hpp: the front door includes sim, beyond the core library (up to mesh)"
      "src/tailor/mesh/inside.cpp: a module includes the front door")
  tailor_layering_violations("${tree}" "geometry;mesh;sim;render" mesh found)
  list(LENGTH found count)
  list(LENGTH expected expected_count)
  set(failed FALSE)
  if(NOT count EQUAL expected_count)
    message(SEND_ERROR "self-test: expected ${expected_count} violations, found ${count}: ${found}")
    set(failed TRUE)
  endif()
  foreach(needle ${expected})
    string(FIND "${found}" "${needle}" at)
    if(at EQUAL -1)
      message(SEND_ERROR "self-test: the check missed \"${needle}\"; it reported: ${found}")
      set(failed TRUE)
    endif()
  endforeach()
  file(REMOVE_RECURSE "${tree}")
  if(NOT failed)
    message(STATUS "layering self-test: all ${expected_count} planted violations reported")
  endif()
  return()
endif()

if(NOT SOURCE_DIR OR NOT LAYERS OR NOT FRONT_DOOR)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=<checkout> -DLAYERS=geometry,mesh,... "
                      "-DFRONT_DOOR=<last core module> -P check_layering.cmake")
endif()
string(REPLACE "," ";" LAYERS "${LAYERS}")
tailor_layering_violations("${SOURCE_DIR}" "${LAYERS}" "${FRONT_DOOR}" found)
if(found)
  list(JOIN found "\n  " text)
  message(FATAL_ERROR "layering violations (order: ${LAYERS}):\n  ${text}")
endif()
string(REPLACE ";" " → " order "${LAYERS}")
message(STATUS "layering: every include under src/tailor follows ${order}; the front door "
               "includes modules up to ${FRONT_DOOR} and no module includes it")
