// gl::PassBindings (halfvec/gl/bindings.hpp): a pass's slots cleared when its scope opens, bound
// through it, released when it closes, and a program that reads an undeclared slot reported as a
// GL_DEBUG_TYPE_ERROR (which tests/gl_errors.cpp turns into a test failure).
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

#include "halfvec/gl/bindings.hpp"
#include "halfvec/gl/objects.hpp"
#include "halfvec/gl/program.hpp"
#include "gl_fixture.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

struct Fixture {
  gl::ProgramCache cache;
  GLuint program = 0;
  gl::Buffer out = gl::createBuffer("out", sizeof(float));
  gl::Buffer in = gl::createBuffer("in", sizeof(float));
  gl::Texture tex = gl::createTexture2D("source", GL_R32F, 1, 1);
  Fixture() {
    program = cache.get(
        {"bindings",
         {{GL_COMPUTE_SHADER, (fs::path(HV_SOURCE_DIR) / "tests/gl/data/bindings.comp").string()}},
         {}});
    const float two = 2.0f, five = 5.0f;
    glNamedBufferSubData(in.id(), 0, sizeof two, &two);
    glTextureSubImage2D(tex.id(), 0, 0, 0, 1, 1, GL_RED, GL_FLOAT, &five);
  }
  float result() const {
    float v = 0.0f;
    glGetNamedBufferSubData(out.id(), 0, sizeof v, &v);
    return v;
  }
};

GLint storageBinding(GLuint slot) {
  GLint id = -1;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, slot, &id);
  return id;
}

GLint textureBinding(GLuint unit) {
  GLint id = -1;
  glGetIntegeri_v(GL_TEXTURE_BINDING_2D, unit, &id);
  return id;
}

const gl::BindingSlots kSlots{};

}  // namespace

TEST(PassBindings, DeclaredPassRunsAndReleasesItsSlots) {
  testContext();
  Fixture f;
  {
    gl::PassBindings b(kSlots, "declared");
    b.use(f.program);
    b.storage(0, f.out.id());
    b.storage(3, f.in.id());
    b.texture(2, f.tex.id());
    EXPECT_TRUE(b.undeclared(f.program).empty());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  EXPECT_FLOAT_EQ(f.result(), 7.0f);
  EXPECT_EQ(storageBinding(0), 0);
  EXPECT_EQ(storageBinding(3), 0);
  EXPECT_EQ(textureBinding(2), 0);
  GLint current = -1;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(current, 0);
}

// What the previous pass left bound is released when the next scope opens: a forgotten bind
// reads nothing, not the other pass's buffer.
TEST(PassBindings, OpeningReleasesWhatOthersLeftBound) {
  testContext();
  Fixture f;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, f.in.id());
  glBindTextureUnit(2, f.tex.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, f.in.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, f.in.id());  // frame-wide below: kept
  gl::BindingSlots slots;
  slots.frame_uniform_mask = 1u;
  {
    gl::PassBindings b(slots, "clears");
    EXPECT_EQ(storageBinding(3), 0);
    EXPECT_EQ(textureBinding(2), 0);
    GLint ubo = -1;
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 1, &ubo);
    EXPECT_EQ(ubo, 0);
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 0, &ubo);
    EXPECT_EQ(ubo, GLint(f.in.id()));
  }
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, 0);
}

// The check fires: the pass forgets storage slot 3 and texture unit 2, which its program reads.
TEST(PassBindings, ReadingAnUndeclaredSlotIsAGlError) {
  testContext();
  Fixture f;
  ASSERT_TRUE(glIsEnabled(GL_DEBUG_OUTPUT));  // the tests' contexts are debug contexts
  std::optional<gl::PassBindings> scope;
  scope.emplace(kSlots, "forgetful");
  gl::PassBindings& b = *scope;
  b.use(f.program);
  b.storage(0, f.out.id());
  {
    const std::vector<std::string> missing = b.undeclared(f.program);
    ASSERT_EQ(missing.size(), 2u);
    EXPECT_NE(missing[0].find("storage buffer 3 (block In)"), std::string::npos) << missing[0];
    EXPECT_NE(missing[1].find("texture unit 2 (t_source)"), std::string::npos) << missing[1];
  }
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  // The scope closes inside the assertion: the GL error names the pass and the slot.
  EXPECT_NONFATAL_FAILURE(scope.reset(), "pass \"forgetful\"");
  EXPECT_FLOAT_EQ(f.result(), 0.0f);  // slot 3 and unit 2 were released: read as nothing
}

TEST(PassBindings, SlotOutsideTheSharedRangeThrows) {
  testContext();
  gl::PassBindings b(kSlots, "range");
  EXPECT_THROW(b.storage(kSlots.storage_buffers, 0), gl::GlError);
  EXPECT_THROW(b.image(kSlots.image_units, 0, GL_READ_ONLY, GL_RGBA8), gl::GlError);
}
