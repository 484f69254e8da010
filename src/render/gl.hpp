// nbscope render: the one way GL is included. Every GL call goes through glad's pointers, never
// through libGL's exported symbols: libGL and libOSMesa both export gl*, and libGL's win when both
// are linked (docs/install.md, "Building from source").
#pragma once
#include <glad/gl.h>

namespace nbscope::render {

// Signature of a context's "get the address of GL function `name`".
using GlProcLoader = void* (*)(const char* name);

// Loads every GL 3.3 core function through `loader` for the current context; Error when the
// context does not provide GL 3.3 core (`where` names the context in the message).
void load_gl(GlProcLoader loader, const char* where);

// Throws Error("<where>: GL error 0x...") when GL reports an error (used after setup steps).
void check_gl(const char* where);

}  // namespace nbscope::render
