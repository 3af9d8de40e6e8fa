# Precompiled third-party headers. Nearly every source file reaches
# Boost.Geometry, Eigen and nlohmann/json through our own headers (vec2.hpp,
# obstacle_field.hpp, route_io.hpp), and each of them costs about 5 s of
# parsing per file; CLI11 costs as much again in every app file. Parsing them
# once per target instead of once per file roughly halves a clean build, which
# CI does twice (Release and sanitizers).
#
# Only third-party and standard headers go in: our own headers must keep
# including what they use (the package_consumer test compiles them without
# any precompiled header). Turn off with -DDEEPGUIDE_PCH=OFF.
set(DEEPGUIDE_PCH_COMMON
  <algorithm> <cmath> <cstddef> <cstdint> <filesystem> <functional> <limits>
  <memory> <optional> <span> <string> <string_view> <utility> <vector>
  <boost/geometry.hpp> <boost/geometry/index/rtree.hpp>
  <Eigen/Core> <nlohmann/json.hpp>)

# deepguide_precompile(TARGET [extra headers...])
function(deepguide_precompile target)
  if(DEEPGUIDE_PCH)
    target_precompile_headers(${target} PRIVATE ${DEEPGUIDE_PCH_COMMON} ${ARGN})
  endif()
endfunction()

# deepguide_precompile_reuse(TARGET FROM): TARGET uses FROM's header (same flags).
function(deepguide_precompile_reuse target from)
  if(DEEPGUIDE_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
