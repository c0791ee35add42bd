#include "halfvec/gl/bindings.hpp"

#include <algorithm>
#include <utility>

#include "halfvec/gl/objects.hpp"

namespace hv::gl {

namespace {

bool inRange(GLenum t, GLenum lo, GLenum hi) {
  return t >= lo && t <= hi;
}

// The opaque uniform types, by their enum ranges in the GL 4.5 registry (the unsigned-int vector
// types sit inside the second sampler range and are left out).
bool isSampler(GLenum t) {
  return inRange(t, GL_SAMPLER_1D, GL_SAMPLER_2D_RECT_SHADOW) ||
         inRange(t, GL_SAMPLER_1D_ARRAY, GL_SAMPLER_CUBE_SHADOW) ||
         inRange(t, GL_INT_SAMPLER_1D, GL_UNSIGNED_INT_SAMPLER_BUFFER) ||
         inRange(t, GL_SAMPLER_CUBE_MAP_ARRAY, GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY) ||
         inRange(t, GL_SAMPLER_2D_MULTISAMPLE, GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY);
}
bool isImage(GLenum t) {
  return inRange(t, GL_IMAGE_1D, GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY);
}

std::string resourceName(GLuint program, GLenum interface, GLuint index) {
  char name[256] = {};
  GLsizei length = 0;
  glGetProgramResourceName(program, interface, index, GLsizei(sizeof name), &length, name);
  return std::string(name, size_t(std::max(length, 0)));
}

bool has(uint32_t mask, GLint slot) {
  return slot >= 0 && slot < 32 && ((mask >> slot) & 1u) != 0;
}

// Releases the slots of `mask`.
void release(uint32_t storage, uint32_t uniform, uint32_t textures, uint32_t images) {
  for (GLuint i = 0; i < 32; ++i) {
    if ((storage >> i) & 1u) glBindBuffersBase(GL_SHADER_STORAGE_BUFFER, i, 1, nullptr);
    if ((uniform >> i) & 1u) glBindBuffersBase(GL_UNIFORM_BUFFER, i, 1, nullptr);
    if ((textures >> i) & 1u) {
      glBindTextures(i, 1, nullptr);
      glBindSamplers(i, 1, nullptr);
    }
    if ((images >> i) & 1u) glBindImageTextures(i, 1, nullptr);
  }
}

uint32_t lowBits(GLuint n) {
  return n >= 32 ? ~0u : (1u << n) - 1u;
}

}  // namespace

PassBindings::PassBindings(const BindingSlots& slots, std::string pass)
    : slots_(slots), pass_(std::move(pass)) {
  for (GLuint n :
       {slots.storage_buffers, slots.uniform_buffers, slots.texture_units, slots.image_units}) {
    if (n > 32) throw GlError("BindingSlots: at most 32 slots of a kind, got " + std::to_string(n));
  }
  release(lowBits(slots.storage_buffers),
          lowBits(slots.uniform_buffers) & ~slots.frame_uniform_mask, lowBits(slots.texture_units),
          lowBits(slots.image_units));
  check_ = glIsEnabled(GL_DEBUG_OUTPUT) == GL_TRUE;
}

PassBindings::~PassBindings() {
  if (check_) {
    for (GLuint program : programs_) {
      const std::vector<std::string> missing = undeclared(program);
      if (missing.empty()) continue;
      std::string text = "pass \"" + pass_ + "\": program " + std::to_string(program) +
                         " reads slots the pass did not bind:";
      for (const std::string& m : missing) text += " " + m + ";";
      // GL_MAX_DEBUG_MESSAGE_LENGTH is at least 1 in the spec, 4096 in practice (Mesa: 4096).
      if (text.size() > 1000) text = text.substr(0, 1000) + "...";
      glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_ERROR, 1,
                           GL_DEBUG_SEVERITY_HIGH, -1, text.c_str());
    }
  }
  if (!programs_.empty()) glUseProgram(0);
  release(storage_, uniform_, textures_, images_);
}

void PassBindings::require(uint32_t& mask, GLuint slot, GLuint count, const char* what) {
  if (slot >= count) {
    throw GlError("pass \"" + pass_ + "\": " + what + " " + std::to_string(slot) +
                  " is outside the " + std::to_string(count) + " the passes share");
  }
  mask |= 1u << slot;
}

void PassBindings::use(GLuint program) {
  glUseProgram(program);
  if (std::find(programs_.begin(), programs_.end(), program) == programs_.end()) {
    programs_.push_back(program);
  }
}

void PassBindings::storage(GLuint slot, GLuint buffer) {
  require(storage_, slot, slots_.storage_buffers, "storage buffer");
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot, buffer);
}

void PassBindings::uniform(GLuint slot, GLuint buffer) {
  require(uniform_, slot, slots_.uniform_buffers, "uniform buffer");
  glBindBufferBase(GL_UNIFORM_BUFFER, slot, buffer);
}

void PassBindings::uniformRange(GLuint slot, GLuint buffer, GLintptr offset, GLsizeiptr size) {
  require(uniform_, slot, slots_.uniform_buffers, "uniform buffer");
  glBindBufferRange(GL_UNIFORM_BUFFER, slot, buffer, offset, size);
}

void PassBindings::texture(GLuint unit, GLuint texture, GLuint sampler) {
  require(textures_, unit, slots_.texture_units, "texture unit");
  glBindTextureUnit(unit, texture);
  glBindSampler(unit, sampler);
}

void PassBindings::image(GLuint unit, GLuint texture, GLenum access, GLenum format, GLint level,
                         GLboolean layered, GLint layer) {
  require(images_, unit, slots_.image_units, "image unit");
  glBindImageTexture(unit, texture, level, layered, layer, access, format);
}

void PassBindings::declareTexture(GLuint unit) {
  require(textures_, unit, slots_.texture_units, "texture unit");
}

std::vector<std::string> PassBindings::undeclared(GLuint program) const {
  std::vector<std::string> out;
  auto blocks = [&](GLenum interface, uint32_t declared, const char* what) {
    GLint n = 0;
    glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &n);
    for (GLint i = 0; i < n; ++i) {
      const GLenum prop = GL_BUFFER_BINDING;
      GLint binding = -1;
      glGetProgramResourceiv(program, interface, GLuint(i), 1, &prop, 1, nullptr, &binding);
      if (!has(declared, binding)) {
        out.push_back(std::string(what) + " " + std::to_string(binding) + " (block " +
                      resourceName(program, interface, GLuint(i)) + ")");
      }
    }
  };
  blocks(GL_SHADER_STORAGE_BLOCK, storage_, "storage buffer");
  blocks(GL_UNIFORM_BLOCK, uniform_ | slots_.frame_uniform_mask, "uniform buffer");
  GLint n = 0;
  glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &n);
  for (GLint i = 0; i < n; ++i) {
    const GLenum props[4] = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE, GL_BLOCK_INDEX};
    GLint v[4] = {0, -1, 0, -1};
    glGetProgramResourceiv(program, GL_UNIFORM, GLuint(i), 4, props, 4, nullptr, v);
    const GLenum type = GLenum(v[0]);
    if (v[3] != -1 || v[1] < 0 || !(isSampler(type) || isImage(type))) continue;
    for (GLint k = 0; k < std::max(v[2], 1); ++k) {
      GLint unit = -1;  // a sampler's or image's value is its unit
      glGetUniformiv(program, v[1] + k, &unit);
      if (!has(isImage(type) ? images_ : textures_, unit)) {
        out.push_back(std::string(isImage(type) ? "image unit " : "texture unit ") +
                      std::to_string(unit) + " (" + resourceName(program, GL_UNIFORM, GLuint(i)) +
                      ")");
      }
    }
  }
  return out;
}

}  // namespace hv::gl
