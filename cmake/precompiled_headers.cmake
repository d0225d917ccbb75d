# Precompiled headers: parsing Eigen, fmt, TBB and the standard headers that almost every
# translation unit includes cost 0.7-3.3 s of each of ~190 compiles (measured with and
# without the precompiled header).
# Each target precompiles them once (the test programs share one: same flags). Turn off to
# check that every file includes what it uses.
option(TAILOR_PRECOMPILE_HEADERS "Precompile the common standard, Eigen, fmt and TBB headers" ON)

set(TAILOR_COMMON_HEADERS
    <algorithm> <array> <cmath> <cstdint> <filesystem> <limits> <memory> <optional> <random>
    <string> <string_view> <vector> <Eigen/Core> <Eigen/Geometry> <fmt/format.h>
    <tbb/parallel_for.h>)

# Precompiles the common headers, plus `ARGN`, for `target`.
function(tailor_precompile_headers target)
  if(TAILOR_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${TAILOR_COMMON_HEADERS} ${ARGN})
  endif()
endfunction()

# Uses the precompiled headers of `from` (a target with the same compile flags).
function(tailor_reuse_precompiled_headers target from)
  if(TAILOR_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
