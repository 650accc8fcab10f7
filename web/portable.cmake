# The portable part of rigidlab built with emscripten, for the page (web/CMakeLists.txt):
# core, the figure descriptions (render's model), the labs' shared layer and every lab
# library, with no GL, no files and no argv. Its dependencies are header-only here
# (Eigen, Boost, nlohmann-json, fmt in header-only mode), taken from Debian's packages
# through a folder of links, since the system include directory itself would shadow
# emscripten's libc.
#
# Sets rigid_root (the source tree) and rigid_portable_labs (every lab library and what
# they need, to link).
get_filename_component(rigid_root ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release)
endif()

set(stage ${CMAKE_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${stage})
foreach(link Eigen:/usr/include/eigen3/Eigen unsupported:/usr/include/eigen3/unsupported
             boost:/usr/include/boost nlohmann:/usr/include/nlohmann fmt:/usr/include/fmt)
  string(REPLACE ":" ";" parts ${link})
  list(GET parts 0 name)
  list(GET parts 1 target)
  if(NOT EXISTS ${stage}/${name})
    file(CREATE_LINK ${target} ${stage}/${name} SYMBOLIC)
  endif()
endforeach()

add_compile_options(-fwasm-exceptions -Wall -Wextra)
add_link_options(-fwasm-exceptions -sALLOW_MEMORY_GROWTH=1)
add_compile_definitions(FMT_HEADER_ONLY)
include_directories(SYSTEM ${stage})
include_directories(${rigid_root}/core/include ${rigid_root}/render/include
                    ${rigid_root}/support/include ${rigid_root}/labs)

file(GLOB core_sources ${rigid_root}/core/src/*.cpp)
add_library(core STATIC ${core_sources})
# The figure descriptions (GL-free) the lab libraries build.
add_library(render_model STATIC ${rigid_root}/render/src/image.cpp
                                ${rigid_root}/render/src/mesh.cpp
                                ${rigid_root}/render/src/plot2d.cpp
                                ${rigid_root}/render/src/scene3d.cpp)
target_include_directories(render_model PRIVATE ${rigid_root}/render/src)

include(${rigid_root}/labs/labs.cmake)
list(TRANSFORM RIGID_LAB_COMMON_SOURCES PREPEND ${rigid_root}/labs/)
add_library(lab_common STATIC ${RIGID_LAB_COMMON_SOURCES})
set(rigid_portable_labs)
foreach(lab IN LISTS RIGID_LABS)
  file(GLOB sources ${rigid_root}/labs/${lab}/*.cpp)
  list(FILTER sources EXCLUDE REGEX "/main\\.cpp$")
  add_library(lab_${lab} STATIC ${sources})
  list(APPEND rigid_portable_labs lab_${lab})
endforeach()
list(APPEND rigid_portable_labs lab_common render_model core)
