# install.cmake: `cmake --install` puts the libraries, their headers, the
# `shadertwin` tool, the built-in shaders, scenes, goldens and materials,
# and a CMake package in a prefix. A user's project then calls
#     find_package(shadertwin REQUIRED)
#     shadertwin_add_technique(NAME ... GLSL ... TWINS ... SCENES ...)
# (cmake/ShadertwinTechnique.cmake; examples/ is such a project).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(_st_libraries st_build_flags st_frame st_texture st_shading st_raster st_kernels st_image st_reference
                  st_optics st_scene st_gl st_app st_sdk)
foreach(_lib IN LISTS _st_libraries)
  string(REGEX REPLACE "^st_" "" _export_name ${_lib})
  set_target_properties(${_lib} PROPERTIES EXPORT_NAME ${_export_name})
endforeach()
install(TARGETS ${_st_libraries} EXPORT shadertwinTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadertwin)
install(TARGETS shadertwin RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The image module (image/image_library.h): bin/shadertwin finds it in
# ../lib, a user's tool on the run path shadertwin::image gives it.
install(TARGETS shadertwin_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})

# Headers keep the source tree's folders, so "shading/program.h" resolves
# from include/shadertwin as it does from the source root.
foreach(_dir frame simd texture shading raster kernels image reference optics scene gl app sdk)
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/${_dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadertwin/${_dir}
          FILES_MATCHING PATTERN "*.h")
endforeach()

# The built-in data, laid out as app/tool_data.h reads it.
set(_share ${CMAKE_INSTALL_DATADIR}/shadertwin)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/glsl/ DESTINATION ${_share}/glsl)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/scenes/ DESTINATION ${_share}/scenes)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/materials/ DESTINATION ${_share}/materials)
# The sweeps' last kept runs, whose charts `report` shows (app/tool_data.h).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/relief-sweep/ DESTINATION ${_share}/sweeps/relief)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/profile-sweep/ DESTINATION ${_share}/sweeps/profile)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/thin-slab-speed/ DESTINATION ${_share}/sweeps/thin-slab)
install(FILES ${SHADERTWIN_GOLDEN_FILE} DESTINATION ${_share}/golden)
install(FILES ${CMAKE_SOURCE_DIR}/sdk/tool_main.cpp DESTINATION ${_share})

set(_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/shadertwin)
install(EXPORT shadertwinTargets NAMESPACE shadertwin:: DESTINATION ${_cmake_dir})
set(SHADERTWIN_DATA_INSTALL_DIR ${_share})
# Whether the libraries hold LTO objects (shadertwinConfig.cmake.in).
if(CMAKE_INTERPROCEDURAL_OPTIMIZATION)
  set(SHADERTWIN_LTO ON)
else()
  set(SHADERTWIN_LTO OFF)
endif()
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/shadertwinConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/cmake/shadertwinConfig.cmake
                              INSTALL_DESTINATION ${_cmake_dir}
                              PATH_VARS SHADERTWIN_DATA_INSTALL_DIR)
# The lane width and instruction set are baked into the libraries: a
# package is for the machine kind it was built on, and says which.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/shadertwinConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/shadertwinConfig.cmake ${CMAKE_BINARY_DIR}/cmake/shadertwinConfigVersion.cmake
              ${CMAKE_SOURCE_DIR}/cmake/ShadertwinTechnique.cmake
        DESTINATION ${_cmake_dir})
