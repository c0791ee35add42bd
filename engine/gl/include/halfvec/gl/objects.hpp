// Move-only RAII wrappers for every GL object kind, created with 4.5 direct state access and named
// with glObjectLabel. Each kind keeps a live count so tests can prove nothing leaks.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "halfvec/gl/gl.hpp"

namespace hv::gl {

enum class Kind {
  Buffer,
  Texture,
  Framebuffer,
  Program,
  Shader,
  VertexArray,
  Query,
  Sampler,
  Count
};

const char* kindName(Kind k);
// Objects of this kind created through the wrappers and not yet destroyed.
int liveCount(Kind k);
int liveCountTotal();

// Thrown for GL failures the caller cannot fix by retrying (incomplete framebuffer, ...).
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {
void destroy(Kind kind, GLuint id);
void noteCreated(Kind kind);
void label(Kind kind, GLuint id, std::string_view name);
}  // namespace detail

template <Kind K>
class Object {
 public:
  Object() = default;
  // Takes ownership of a freshly created id.
  explicit Object(GLuint id, std::string_view name = {}) : id_(id) {
    if (id_ != 0) {
      detail::noteCreated(K);
      if (!name.empty()) detail::label(K, id_, name);
    }
  }
  ~Object() { reset(); }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Object& operator=(Object&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  void reset() {
    if (id_ != 0) detail::destroy(K, std::exchange(id_, 0));
  }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  GLuint id_ = 0;
};

using Buffer = Object<Kind::Buffer>;
using Texture = Object<Kind::Texture>;
using Framebuffer = Object<Kind::Framebuffer>;
using Program = Object<Kind::Program>;
using Shader = Object<Kind::Shader>;
using VertexArray = Object<Kind::VertexArray>;
using Query = Object<Kind::Query>;
using Sampler = Object<Kind::Sampler>;

// Factories (DSA). `flags` as for glNamedBufferStorage.
Buffer createBuffer(std::string_view name, std::size_t bytes, const void* data = nullptr,
                    GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
Texture createTexture2D(std::string_view name, GLenum internal_format, int width, int height,
                        int levels = 1);
Texture createTextureCube(std::string_view name, GLenum internal_format, int size, int levels);
VertexArray createVertexArray(std::string_view name);
Query createQuery(std::string_view name, GLenum target);
Sampler createSampler(std::string_view name);

struct ColorAttachment {
  const Texture* texture;
  int level = 0;
};
// Checks completeness; throws GlError naming the framebuffer and the status otherwise.
Framebuffer createFramebuffer(std::string_view name, std::initializer_list<ColorAttachment> colors,
                              const Texture* depth = nullptr);

int mipLevelsFor(int width, int height);

}  // namespace hv::gl
