#include "halfvec/gl/objects.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <string>

namespace hv::gl {
namespace {
std::array<std::atomic<int>, static_cast<size_t>(Kind::Count)> g_live{};

GLenum labelNamespace(Kind k) {
  switch (k) {
    case Kind::Buffer:
      return GL_BUFFER;
    case Kind::Texture:
      return GL_TEXTURE;
    case Kind::Framebuffer:
      return GL_FRAMEBUFFER;
    case Kind::Program:
      return GL_PROGRAM;
    case Kind::Shader:
      return GL_SHADER;
    case Kind::VertexArray:
      return GL_VERTEX_ARRAY;
    case Kind::Query:
      return GL_QUERY;
    case Kind::Sampler:
      return GL_SAMPLER;
    case Kind::Count:
      break;
  }
  return GL_NONE;
}
}  // namespace

const char* kindName(Kind k) {
  static constexpr const char* names[] = {"buffer", "texture",      "framebuffer", "program",
                                          "shader", "vertex array", "query",       "sampler"};
  return names[static_cast<size_t>(k)];
}

int liveCount(Kind k) {
  return g_live[static_cast<size_t>(k)].load();
}

int liveCountTotal() {
  int n = 0;
  for (auto& c : g_live) n += c.load();
  return n;
}

namespace detail {
void noteCreated(Kind kind) {
  ++g_live[static_cast<size_t>(kind)];
}

void label(Kind kind, GLuint id, std::string_view name) {
  GLint max_len = 256;
  glGetIntegerv(GL_MAX_LABEL_LENGTH, &max_len);
  const auto n = static_cast<GLsizei>(std::min<size_t>(name.size(), size_t(max_len - 1)));
  glObjectLabel(labelNamespace(kind), id, n, name.data());
}

void destroy(Kind kind, GLuint id) {
  switch (kind) {
    case Kind::Buffer:
      glDeleteBuffers(1, &id);
      break;
    case Kind::Texture:
      glDeleteTextures(1, &id);
      break;
    case Kind::Framebuffer:
      glDeleteFramebuffers(1, &id);
      break;
    case Kind::Program:
      glDeleteProgram(id);
      break;
    case Kind::Shader:
      glDeleteShader(id);
      break;
    case Kind::VertexArray:
      glDeleteVertexArrays(1, &id);
      break;
    case Kind::Query:
      glDeleteQueries(1, &id);
      break;
    case Kind::Sampler:
      glDeleteSamplers(1, &id);
      break;
    case Kind::Count:
      return;
  }
  --g_live[static_cast<size_t>(kind)];
}
}  // namespace detail

Buffer createBuffer(std::string_view name, std::size_t bytes, const void* data, GLbitfield flags) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  Buffer b(id, name);
  // Zero-sized storage is invalid in GL; keep one byte so empty lists still bind.
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes == 0 ? 16 : bytes),
                       bytes == 0 ? nullptr : data, flags);
  return b;
}

Texture createTexture2D(std::string_view name, GLenum internal_format, int width, int height,
                        int levels) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  Texture t(id, name);
  glTextureStorage2D(id, levels, internal_format, width, height);
  return t;
}

Texture createTextureCube(std::string_view name, GLenum internal_format, int size, int levels) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
  Texture t(id, name);
  glTextureStorage2D(id, levels, internal_format, size, size);
  return t;
}

VertexArray createVertexArray(std::string_view name) {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id, name);
}

Query createQuery(std::string_view name, GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return Query(id, name);
}

Sampler createSampler(std::string_view name) {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  return Sampler(id, name);
}

Framebuffer createFramebuffer(std::string_view name, std::initializer_list<ColorAttachment> colors,
                              const Texture* depth) {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  Framebuffer fb(id, name);
  std::array<GLenum, 8> draw{};
  GLsizei n = 0;
  for (const auto& c : colors) {
    glNamedFramebufferTexture(id, GL_COLOR_ATTACHMENT0 + n, c.texture->id(), c.level);
    draw[n] = GL_COLOR_ATTACHMENT0 + n;
    ++n;
  }
  if (n > 0) {
    glNamedFramebufferDrawBuffers(id, n, draw.data());
  } else {
    glNamedFramebufferDrawBuffer(id, GL_NONE);
  }
  if (depth) glNamedFramebufferTexture(id, GL_DEPTH_ATTACHMENT, depth->id(), 0);
  const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw GlError("framebuffer '" + std::string(name) + "' is incomplete (status 0x" + [&] {
      char buf[16];
      std::snprintf(buf, sizeof buf, "%04X", status);
      return std::string(buf);
    }() + ")");
  }
  return fb;
}

int mipLevelsFor(int width, int height) {
  return 1 + static_cast<int>(std::floor(std::log2(std::max(1, std::max(width, height)))));
}

}  // namespace hv::gl
