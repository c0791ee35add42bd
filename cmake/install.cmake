# `cmake --install` for halfvec as a CMake package: find_package(halfvec CONFIG REQUIRED) gives
# halfvec::engine (everything but the UI) and the module targets halfvec::<module>
# (engine/CMakeLists.txt). Installs the static libraries, the public headers under
# include/halfvec/<module>/, the shared GLSL headers the C++ headers include
# (include/halfvec/shaders/common), the shaders for editing and hot reload
# (share/halfvec/shaders; the libraries carry an embedded copy and need no file at run time),
# and, when built, the halfvec program with the sample scenes (bin/, share/halfvec/scenes).
include(CMakePackageConfigHelpers)

get_property(hv_modules GLOBAL PROPERTY HV_MODULES)
set(hv_targets halfvec_engine halfvec_imgui_backends)
foreach(m ${hv_modules})
  list(APPEND hv_targets halfvec_${m})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/${m}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

install(TARGETS ${hv_targets} EXPORT halfvecTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT halfvecTargets NAMESPACE halfvec:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/halfvec)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/common DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/halfvec/shaders
        FILES_MATCHING PATTERN "*.glsl")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/ DESTINATION ${CMAKE_INSTALL_DATADIR}/halfvec/shaders
        FILES_MATCHING PATTERN "*.glsl" PATTERN "*.vert" PATTERN "*.frag" PATTERN "*.comp")

if(TARGET halfvec)
  install(TARGETS halfvec RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/samples/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/halfvec/scenes)
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/halfvecConfig.cmake.in
  ${PROJECT_BINARY_DIR}/halfvecConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/halfvec)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/halfvecConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/halfvecConfig.cmake ${PROJECT_BINARY_DIR}/halfvecConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/halfvec)
