# The one list of labs, and the shared layer's sources every build of the labs compiles
# (the native one, labs/CMakeLists.txt; the WebAssembly one, web/portable.cmake).
#
# The labs, in section order. The list drives the build, the `figures`
# target (figures/ and the gallery), scripts/run-labs, the lab-contract
# and JSON-schema tests and the golden-image tests. A new lab is its folder,
# one line here, its goldens and its page (CONTRIBUTING.md, "Adding a lab").
set(RIGID_LABS
  lamina_tensor
  tire_balancing
  poinsot
  tennis_racquet
  football
  euler_angles
  top_nutation
  CACHE INTERNAL "rigidlab's labs, in section order")

# The shared layer every lab library builds on (common/, paths relative to labs/): its
# inputs' rules, its Report and the writers, the integrated bodies' shared reporting, the
# shared scenes, the live session. No files, no windows, no argv: it builds wherever core
# does (emscripten too).
set(RIGID_LAB_COMMON_SOURCES
  common/inputs.cpp
  common/report.cpp
  common/writers.cpp
  common/integrated_run.cpp
  common/integrated_motion.cpp
  common/free_motion.cpp
  common/free_body_scenes.cpp
  common/integrator_plot.cpp
  common/session.cpp)
