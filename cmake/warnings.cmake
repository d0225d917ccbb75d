# Warnings for the project's own targets; our code builds without any.
function(tailor_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  # A unity build includes each .cpp into a batch file, and GCC then takes a class of one
  # .cpp holding a type from its anonymous namespace for a header's (a false warning).
  if(CMAKE_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
  endif()
endfunction()
