// Dear ImGui's OpenGL 3 renderer backend, compiled from the source Debian ships, against glad.
// Debian's precompiled copy loads GL by dlopen'ing libGL and so fails under OSMesa; this copy
// calls every GL function through glad's pointers, which work for both contexts.
#include <glad/gl.h>

#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#include "imgui_impl_opengl3.cpp"  // NOLINT(bugprone-suspicious-include)
