# Warnings for the project's own targets; our code builds without any.
function(tailor_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
