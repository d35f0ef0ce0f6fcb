# The Debian package of what `cmake --install` installs, under /usr: `cpack --config build/CPackConfig.cmake` writes
# build/hexc_<version>_amd64.deb (README.md, docs/build-integration.md). Included by the top-level CMakeLists.txt.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME hexc)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # hexc_<version>_<architecture>.deb
# Installed with DESTDIR and the prefix /usr, so that a rule choosing by the prefix (the Python package's folder,
# integrations/python/CMakeLists.txt) sees /usr, not CPack's staging folder.
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)
set(HEXC_PACKAGE_MAINTAINER "hexc maintainers <maintainers@hexc.invalid>" CACHE STRING
    "The Debian package's Maintainer field: a name and an address")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${HEXC_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The summary, then the long description; CPack indents it and turns the empty line into " .". Lines stay under 80
# columns, as Debian policy asks.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "material compiler injecting hex-tiling into shaders
hexc reads material descriptions (JSON or MaterialX), injects hex-tiling
sampling (Mikkelsen 2022) into every texture slot of a shader template, and
writes SPIR-V, HLSL, GLSL, MSL and WGSL with a reflection manifest, or packages
for Godot, Filament, three.js, Babylon.js, Unity and Unreal.

This package holds the hexc command line, libhexc (a static C++ library with a
C API) and its headers, the CMake package (find_package(hexc)), the Bazel
rules, the Python module (import hexc) and the documentation.")
# The libraries hexc and the Python module load, from dpkg-shlibdeps; the Python the module is built for.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
get_property(python_version GLOBAL PROPERTY hexc_python_version)
if(python_version)
  string(REPLACE "." ";" parts ${python_version})
  list(GET parts 1 minor)
  math(EXPR next_minor "${minor} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${python_version}~), python3 (<< 3.${next_minor})")
endif()
# Recommended, so installed with the package unless apt is told otherwise: the Vulkan loader and lavapipe, which
# `hexc render` and `preview` load at run time (without them they exit 4 and compiling still works), and the
# development packages libhexc is linked with, which find_package(hexc COMPONENTS library) finds (the tool needs none);
# glslang-tools too, as glslang's CMake package names its glslangValidator, which glslang-dev does not bring.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libvulkan1, mesa-vulkan-drivers, glslang-dev, glslang-tools, spirv-tools, \
libspirv-cross-c-shared-dev, nlohmann-json3-dev, libopenexr-dev, libpugixml-dev, libstb-dev, libxxhash-dev, pkg-config")
# Debian policy's other parts that CPack can make (tests/package/policy.py checks them): a Debian revision (a version
# without one is a native package's, whose changelog would be changelog.gz); the binaries stripped (their linker's
# build id, which `hexc --version` shows, stays); and, in the package only, not in `cmake --install`'s prefix, the
# copyright file in DEP-5's format and changelog.Debian.gz, compressed by gzip -9n: no name, no time, the same bytes
# from the same text.
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_STRIP_FILES ON)
file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/changelog changelog_top LIMIT_COUNT 1)
if(NOT changelog_top MATCHES "^hexc \\(${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE}\\) ")
  message(FATAL_ERROR "compiler/cmake/debian/changelog's first entry is not for hexc "
    "${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE}: ${changelog_top}")
endif()
set(changelog_gz ${PROJECT_BINARY_DIR}/debian/changelog.Debian.gz)
file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/debian)
execute_process(COMMAND gzip -9n -c ${CMAKE_CURRENT_LIST_DIR}/changelog OUTPUT_FILE ${changelog_gz}
                COMMAND_ERROR_IS_FATAL ANY)
set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY
             CMAKE_CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/changelog)
include(GNUInstallDirs)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/copyright ${changelog_gz} DESTINATION ${CMAKE_INSTALL_DOCDIR}
        COMPONENT debian EXCLUDE_FROM_ALL)
# What `cmake --install` installs (ALL), then those two.
set(CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR};hexc;ALL;/;${PROJECT_BINARY_DIR};hexc;debian;/")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${CMAKE_CURRENT_LIST_DIR}/prerm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
