# `cpack -G DEB` in the build directory: nbscope_VERSION_ARCH.deb, installed under /usr (docs/install.md).
# Depends: what the binary links, found by dpkg-shlibdeps (libglfw3, libbox2d2, libstb0, libstdc++6,
# ...), and what it dlopens, named here: libGL for the window (GLFW opens it), libOSMesa or libEGL
# off-screen (src/render/gl_context.cpp); either off-screen library will do.
set(CPACK_PACKAGE_NAME nbscope)
set(CPACK_PACKAGE_VENDOR nbscope)
set(CPACK_PACKAGE_CONTACT "nbscope maintainers <nbscope@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "visual debugger for grid-based contact detection (Munjiza-NBS)")
set(CPACK_PACKAGE_DESCRIPTION "Watches Munjiza-NBS and its ancestors map moving bodies onto cells and singly connected lists,
checks every frame against brute force and Box2D, in a window or headless, and loads your own detector as a plugin.")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_STRIP_FILES ON)  # the release preset's line tables are for profiling here, not for users
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(nbscope_dlopened "")
if(NBSCOPE_GUI)
  set(offscreen "")
  if(NBSCOPE_OSMESA_INCLUDE)
    list(APPEND offscreen libosmesa6)
  endif()
  if(NBSCOPE_EGL_INCLUDE)
    list(APPEND offscreen libegl1)
  endif()
  list(JOIN offscreen " | " offscreen)
  set(nbscope_dlopened "libgl1, ${offscreen}")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${nbscope_dlopened}")
set(CPACK_GENERATOR DEB)
include(CPack)
