# ShadertwinTechnique.cmake: shadertwin_add_technique(), which builds a
# user's GLSL programs, their C++ twins and scene kinds into a shadertwin
# tool (docs/adding-a-technique.md).
#
#   shadertwin_add_technique(
#     NAME glow                      # a C identifier; SHADERTWIN_TECHNIQUE(glow, r) in C++ registers it
#     [TOOL glowtwin]                # the tool's target (default: shadertwin); several techniques may share one
#     GLSL glsl/glow.vert glsl/glow.frag ...   # the real shaders, run on llvmpipe (also .glsl includes)
#     TWINS kernels/glow_vert.cpp kernels/glow_frag.cpp ...   # their twins, and any other C++ of the technique
#     [SCENES scenes/ | scenes/a.json ...]     # the technique's scenes (folders or files)
#     [GOLDEN golden/hashes.json])   # where `golden` keeps their hashes (default: golden/<NAME>.json)
#
# The tool has every shadertwin command (render, compare, golden, bench,
# report, sweep, ...) for the technique's scenes and the built-in ones.
# With enable_testing(), each of the technique's scenes is also two CTest
# tests, <NAME>.<scene>.compare (both backends against the scene's
# criteria) and <NAME>.<scene>.golden (the CPU image against the golden
# hash), labelled <NAME>, so `ctest -L <NAME>` runs them.
# Relative paths are taken from the calling CMakeLists.txt's folder.
#
# SHADERTWIN_LTO=ON|OFF: link the tool with link-time optimisation. ON
# inlines the GLSL math and the pipeline into the twins (the speed `bench`
# should measure) but makes every link a minute long; OFF links in seconds,
# for the edit-compare loop. Default: ON for Release and MinSizeRel builds,
# OFF otherwise (Debug, RelWithDebInfo, none). The images are the same
# either way (tests/sdk_test.sh checks the example's hashes in both).

function(_shadertwin_absolute out)
  set(result)
  foreach(path IN LISTS ARGN)
    cmake_path(ABSOLUTE_PATH path BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE abs)
    list(APPEND result "${abs}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# A C++ initializer list of raw string literals.
function(_shadertwin_cpp_strings out)
  set(result "")
  foreach(s IN LISTS ARGN)
    string(APPEND result "R\"st(${s})st\", ")
  endforeach()
  set(${out} "{${result}}" PARENT_SCOPE)
endfunction()

# Whether the tool links with LTO (SHADERTWIN_LTO above).
function(_shadertwin_lto out)
  if(DEFINED SHADERTWIN_LTO)
    set(want ${SHADERTWIN_LTO})
  elseif(CMAKE_BUILD_TYPE MATCHES "^(Release|MinSizeRel)$")
    set(want ON)
  else()
    set(want OFF)
  endif()
  if(want AND NOT shadertwin_LTO)
    if(DEFINED SHADERTWIN_LTO)
      message(WARNING "SHADERTWIN_LTO=ON, but the installed shadertwin libraries hold no LTO objects: linking without")
    endif()
    set(want OFF)
  endif()
  if(want)
    set(${out} ON PARENT_SCOPE)
  else()
    set(${out} OFF PARENT_SCOPE)
  endif()
endfunction()

function(shadertwin_add_technique)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "NAME;TOOL;GOLDEN" "GLSL;TWINS;SCENES")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "shadertwin_add_technique: unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_NAME MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "shadertwin_add_technique: NAME '${ARG_NAME}' must be a C identifier (it names SHADERTWIN_TECHNIQUE(NAME, ...))")
  endif()
  set(where "shadertwin_add_technique(${ARG_NAME})")
  if(NOT ARG_GLSL)
    message(FATAL_ERROR "${where}: no GLSL files")
  endif()
  if(NOT ARG_TWINS)
    message(FATAL_ERROR "${where}: no TWINS sources")
  endif()
  if(NOT ARG_TOOL)
    set(ARG_TOOL shadertwin)
  endif()
  if(NOT ARG_GOLDEN)
    set(ARG_GOLDEN "golden/${ARG_NAME}.json")
  endif()

  _shadertwin_absolute(glsl ${ARG_GLSL})
  _shadertwin_absolute(twins ${ARG_TWINS})
  _shadertwin_absolute(scenes ${ARG_SCENES})
  _shadertwin_absolute(golden ${ARG_GOLDEN})
  foreach(file IN LISTS glsl twins)
    if(NOT EXISTS "${file}" OR IS_DIRECTORY "${file}")
      message(FATAL_ERROR "${where}: no file ${file}")
    endif()
  endforeach()
  foreach(file IN LISTS glsl)
    if(NOT file MATCHES "\\.(vert|frag|glsl)$")
      message(FATAL_ERROR "${where}: GLSL file ${file} is not a .vert, .frag or .glsl file")
    endif()
  endforeach()
  foreach(path IN LISTS scenes)
    if(NOT EXISTS "${path}")
      message(FATAL_ERROR "${where}: no scene file or folder ${path}")
    endif()
  endforeach()

  if(NOT TARGET ${ARG_TOOL})
    add_executable(${ARG_TOOL} "${shadertwin_DATA_DIR}/tool_main.cpp")
    target_link_libraries(${ARG_TOOL} PRIVATE shadertwin::sdk)
    _shadertwin_lto(lto)
    # With LTO the link gets -flto=auto (parallel jobs) and the twins join
    # the inlining; without, the libraries' fat objects link as plain code.
    set_property(TARGET ${ARG_TOOL} PROPERTY INTERPROCEDURAL_OPTIMIZATION ${lto})
    if(NOT lto AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_link_options(${ARG_TOOL} PRIVATE -fno-lto)
    endif()
  endif()
  get_target_property(techniques ${ARG_TOOL} SHADERTWIN_TECHNIQUES)
  if(techniques AND ARG_NAME IN_LIST techniques)
    message(FATAL_ERROR "${where}: tool ${ARG_TOOL} already has a technique ${ARG_NAME}")
  endif()
  set_property(TARGET ${ARG_TOOL} APPEND PROPERTY SHADERTWIN_TECHNIQUES ${ARG_NAME})

  # The declaration the tool takes in when it starts (sdk/technique.h).
  _shadertwin_cpp_strings(glsl_list ${glsl})
  _shadertwin_cpp_strings(scene_list ${scenes})
  set(declaration "${CMAKE_CURRENT_BINARY_DIR}/shadertwin_technique_${ARG_NAME}.cpp")
  file(CONFIGURE OUTPUT "${declaration}" @ONLY CONTENT [=[
// Generated by shadertwin_add_technique(@ARG_NAME@): the technique's files,
// for the tool to take in when it starts. Do not edit.
#include "sdk/technique.h"

SHADERTWIN_TECHNIQUE(@ARG_NAME@, registry);

namespace {
const st::TechniqueDeclaration declaration{
    "@ARG_NAME@", shadertwin_technique_@ARG_NAME@, @glsl_list@, @scene_list@,
    R"st(@golden@)st", R"st(@shadertwin_DATA_DIR@)st"};
}  // namespace
]=])
  target_sources(${ARG_TOOL} PRIVATE ${twins} "${declaration}")

  set(scene_files)
  foreach(path IN LISTS scenes)
    if(IS_DIRECTORY "${path}")
      file(GLOB found CONFIGURE_DEPENDS "${path}/*.json")
      list(APPEND scene_files ${found})
    else()
      list(APPEND scene_files "${path}")
    endif()
  endforeach()
  foreach(file IN LISTS scene_files)
    cmake_path(GET file STEM LAST_ONLY scene)
    add_test(NAME ${ARG_NAME}.${scene}.compare
             COMMAND ${ARG_TOOL} compare ${scene} --out "${CMAKE_CURRENT_BINARY_DIR}/shadertwin-tests")
    add_test(NAME ${ARG_NAME}.${scene}.golden COMMAND ${ARG_TOOL} golden check ${scene})
    set_tests_properties(${ARG_NAME}.${scene}.compare ${ARG_NAME}.${scene}.golden PROPERTIES LABELS "${ARG_NAME}")
  endforeach()
endfunction()
