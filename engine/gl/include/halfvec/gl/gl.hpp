// The one include for OpenGL 4.5 core. Entry points come straight from glvnd's libOpenGL, which
// exports every core function, so no loader is needed for an EGL or GLFW context.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
