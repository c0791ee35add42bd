// A pass's resource bindings declared, bound and released in one place (STYLE.md 9: a pass is a
// named scope). Binding points are shared by every pass, and a renderer may give one slot
// different meanings in passes that do not run together (halfvec's bindings.glsl does), so a
// forgotten bind would read whatever the previous pass left there, without an error. A
// PassBindings scope:
//  - on opening, releases every slot of its BindingSlots (storage and uniform buffers, texture
//    units with their samplers, image units), except the frame-wide uniform blocks: what the pass
//    does not bind reads nothing, never another pass's buffer;
//  - binds through its functions, which declare the slot;
//  - on closing, releases what it declared and, when GL debug output is on (the debug contexts
//    the tests and the viewer create), checks every program made current through use() against
//    the declared slots by program introspection (the active storage blocks, uniform blocks,
//    samplers and images and their bindings): a program that reads a slot the pass did not
//    declare is reported as a GL_DEBUG_TYPE_ERROR message (glDebugMessageInsert), which fails
//    the test that rendered (tests/gl_errors.cpp) and is logged as an error otherwise.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "halfvec/gl/gl.hpp"

namespace hv::gl {

// The binding points a renderer's passes use, cleared when a scope opens. Each count is at most
// 32 and at most the GL 4.5 minimum of its limit, so that clearing never names a slot the
// implementation lacks.
struct BindingSlots {
  GLuint storage_buffers = 8;  // GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS >= 8
  GLuint uniform_buffers = 8;  // GL_MAX_UNIFORM_BUFFER_BINDINGS >= 72 (84 in 4.5)
  GLuint texture_units = 16;   // GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS >= 80
  GLuint image_units = 8;      // GL_MAX_IMAGE_UNITS >= 8
  // Uniform-buffer slots bound for the whole frame (bit i: slot i): neither cleared nor required
  // to be declared.
  uint32_t frame_uniform_mask = 0;
};

class PassBindings {
 public:
  PassBindings(const BindingSlots& slots, std::string pass);
  ~PassBindings();
  PassBindings(const PassBindings&) = delete;
  PassBindings& operator=(const PassBindings&) = delete;

  // glUseProgram, and the program is checked when the scope closes.
  void use(GLuint program);
  void storage(GLuint slot, GLuint buffer);
  void uniform(GLuint slot, GLuint buffer);
  void uniformRange(GLuint slot, GLuint buffer, GLintptr offset, GLsizeiptr size);
  // A texture and its sampler on `unit` (sampler 0: the texture's own parameters).
  void texture(GLuint unit, GLuint texture, GLuint sampler = 0);
  void image(GLuint unit, GLuint texture, GLenum access, GLenum format, GLint level = 0,
             GLboolean layered = GL_FALSE, GLint layer = 0);
  // Declares a texture unit that code outside the scope binds itself (e.g. the shadow atlas): it
  // is checked and released like the others.
  void declareTexture(GLuint unit);

  // The slots `program` reads that the scope has not declared, one line each ("storage buffer 3
  // (block LightBlock)"); empty when it reads only what was declared.
  std::vector<std::string> undeclared(GLuint program) const;

 private:
  void require(uint32_t& mask, GLuint slot, GLuint count, const char* what);
  BindingSlots slots_;
  std::string pass_;
  uint32_t storage_ = 0, uniform_ = 0, textures_ = 0, images_ = 0;  // declared, bit per slot
  std::vector<GLuint> programs_;
  bool check_ = false;  // GL debug output is on: check the programs at close
};

}  // namespace hv::gl
