#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "halfvec/gl/objects.hpp"
#include "halfvec/gl/program.hpp"
#include "halfvec/gl/shader_source.hpp"
#include "halfvec/gl/timer.hpp"
#include "gl_fixture.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {
fs::path dataDir() {
  return fs::path(HV_SOURCE_DIR) / "tests" / "gl" / "data";
}
}  // namespace

TEST(Context, HeadlessCreatesGl45Core) {
  Context& ctx = testContext();
  GLint major = 0, minor = 0, flags = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &flags);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(flags & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_FALSE(ctx.renderer().empty());
  EXPECT_NE(ctx.platform().find("EGL"), std::string::npos);
}

TEST(Context, ImpossibleVersionGivesClearError) {
  testContext();  // keep the main context alive; a failing one must not disturb it
  ContextOptions o;
  o.gl_major = 9;
  o.gl_minor = 9;
  try {
    auto c = createHeadlessContext(o);
    FAIL() << "a 9.9 context should not exist";
  } catch (const ContextError& e) {
    EXPECT_NE(std::string(e.what()).find("9.9"), std::string::npos) << e.what();
  }
}

TEST(Resources, WrappersFreeEverything) {
  testContext();
  const int before = gl::liveCountTotal();
  {
    auto tex = gl::createTexture2D("t", GL_RGBA8, 16, 16);
    auto depth = gl::createTexture2D("d", GL_DEPTH_COMPONENT32F, 16, 16);
    auto fb = gl::createFramebuffer("fb", {{&tex}}, &depth);
    auto buf = gl::createBuffer("b", 64);
    auto vao = gl::createVertexArray("vao");
    auto q = gl::createQuery("q", GL_TIMESTAMP);
    EXPECT_EQ(gl::liveCountTotal(), before + 6);
    EXPECT_TRUE(glIsTexture(tex.id()));
    const GLuint id = buf.id();
    gl::Buffer moved = std::move(buf);
    EXPECT_EQ(buf.id(), 0u);
    EXPECT_EQ(moved.id(), id);
    char label[64] = {};
    glGetObjectLabel(GL_TEXTURE, tex.id(), sizeof label, nullptr, label);
    EXPECT_STREQ(label, "t");
  }
  EXPECT_EQ(gl::liveCountTotal(), before);
}

TEST(Resources, IncompleteFramebufferThrows) {
  testContext();
  auto tex = gl::createTexture2D("color", GL_RGBA8, 16, 16);
  auto depth = gl::createTexture2D("odd depth", GL_DEPTH_COMPONENT32F, 8, 4);
  auto bad = gl::createTexture2D("not renderable", GL_COMPRESSED_RGBA_BPTC_UNORM, 16, 16);
  EXPECT_THROW(gl::createFramebuffer("bad", {{&bad}}), gl::GlError);
}

TEST(ShaderSource, IncludesAndDefinesAfterVersion) {
  const auto src = gl::expandShader(dataDir() / "good.comp", {{"VALUE", "21.0"}});
  EXPECT_EQ(src.text.rfind("#version 450 core\n#define VALUE 21.0\n", 0), 0u) << src.text;
  EXPECT_NE(src.text.find("float twice"), std::string::npos);
  EXPECT_EQ(src.files.size(), 2u);
}

TEST(ShaderSource, MissingIncludeNamesFileAndLine) {
  const fs::path tmp = fs::temp_directory_path() / "hv_missing_inc.frag";
  { std::ofstream(tmp) << "#version 450 core\n\n#include \"nope.glsl\"\nvoid main() {}\n"; }
  try {
    gl::expandShader(tmp, {});
    FAIL();
  } catch (const gl::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("hv_missing_inc.frag:3"), std::string::npos) << e.what();
  }
}

TEST(ShaderSource, DefineKeyIsCanonical) {
  EXPECT_EQ(gl::defineKey({{"B", "1"}, {"A", "0"}}), gl::defineKey({{"A", "0"}, {"B", "1"}}));
}

TEST(Program, CompileErrorNamesOriginalFileAndLine) {
  testContext();
  gl::ProgramDesc d{
      "broken", {{GL_FRAGMENT_SHADER, (dataDir() / "broken_main.frag").string()}}, {}};
  try {
    gl::buildProgram(d);
    FAIL() << "the broken shader compiled";
  } catch (const gl::ShaderError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("broken_inc.glsl:4"), std::string::npos) << msg;
  }
}

TEST(Program, CacheCompilesOncePerVariantAndRuns) {
  testContext();
  gl::ProgramCache cache;
  gl::ProgramDesc d{
      "good", {{GL_COMPUTE_SHADER, (dataDir() / "good.comp").string()}}, {{"VALUE", "21.0"}}};
  const GLuint p1 = cache.get(d);
  EXPECT_EQ(cache.get(d), p1);
  d.defines[0].value = "4.0";
  const GLuint p2 = cache.get(d);
  EXPECT_NE(p1, p2);
  EXPECT_EQ(cache.variants().size(), 2u);
  auto buf = gl::createBuffer("out", sizeof(float));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf.id());
  glUseProgram(p1);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  float v = 0;
  glGetNamedBufferSubData(buf.id(), 0, sizeof v, &v);
  EXPECT_FLOAT_EQ(v, 42.0f);
  glUseProgram(0);
}

TEST(Timer, ReportsEveryPass) {
  testContext();
  gl::PassTimer timer;
  {
    gl::ScopedPass a(timer, "a");
    glFinish();
  }
  { gl::ScopedPass b(timer, "b"); }
  auto r = timer.resolve();
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].first, "a");
  EXPECT_GE(r[0].second, 0.0);
  EXPECT_EQ(r[1].first, "b");
}

// Shader hot reload: a broken edit throws naming file:line and leaves the last good program in
// place and running; a good edit replaces it.
TEST(Program, ReloadAllKeepsLastGoodProgramOnError) {
  testContext();
  const fs::path dir = fs::temp_directory_path() / "hv_reload_shader";
  fs::create_directories(dir);
  const fs::path file = dir / "value.comp";
  auto writeShader = [&](const std::string& body) {
    std::ofstream(file) << "#version 450 core\nlayout(local_size_x = 1) in;\n"
                           "layout(std430, binding = 0) buffer Out { float values[]; };\n"
                        << body << "\n";
  };
  auto run = [&](GLuint prog) {
    auto buf = gl::createBuffer("out", sizeof(float));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf.id());
    glUseProgram(prog);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    float v = 0;
    glGetNamedBufferSubData(buf.id(), 0, sizeof v, &v);
    glUseProgram(0);
    return v;
  };
  writeShader("void main() { values[0] = 42.0; }");
  gl::ProgramCache cache;
  const gl::ProgramDesc d{"reload", {{GL_COMPUTE_SHADER, file.string()}}, {}};
  const GLuint good = cache.get(d);
  EXPECT_FLOAT_EQ(run(good), 42.0f);

  writeShader("void main() { values[0] = undefined_thing; }");  // line 4
  try {
    cache.reloadAll();
    FAIL() << "the broken edit compiled";
  } catch (const gl::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("value.comp:4"), std::string::npos) << e.what();
  }
  EXPECT_EQ(cache.get(d), good);
  EXPECT_FLOAT_EQ(run(cache.get(d)), 42.0f);

  writeShader("void main() { values[0] = 7.0; }");
  cache.reloadAll();
  EXPECT_FLOAT_EQ(run(cache.get(d)), 7.0f);
  fs::remove_all(dir);
}

// tests/gl_errors.cpp makes any GL API error a failure of the test that caused it: binding a
// texture name that was never created is GL_INVALID_OPERATION in a core profile.
TEST(GlDebug, ApiErrorFailsTheTest) {
  testContext();
  EXPECT_NONFATAL_FAILURE(glBindTexture(GL_TEXTURE_2D, 0x7fffffffu), "GL_DEBUG_TYPE_ERROR");
}
