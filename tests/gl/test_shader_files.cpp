// Where shaders come from (halfvec/gl/shader_source.hpp): the copy embedded in the library by
// default, a folder on request; the library never needs the source tree at run time.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "halfvec/gl/shader_source.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

const fs::path kSourceShaders = fs::path(HV_SOURCE_DIR) / "shaders";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Unsets HV_SHADER_DIR and the program's folder for the test's duration.
struct DefaultRoot {
  std::string saved;
  bool had = false;
  DefaultRoot() {
    if (const char* e = std::getenv("HV_SHADER_DIR")) {
      had = true;
      saved = e;
    }
    ::unsetenv("HV_SHADER_DIR");
    gl::setShaderDir({});
  }
  ~DefaultRoot() {
    if (had) ::setenv("HV_SHADER_DIR", saved.c_str(), 1);
    gl::setShaderDir({});
  }
};

}  // namespace

// Every file under shaders/ is embedded, byte for byte (so the build's copy is never stale).
TEST(ShaderFiles, EmbeddedCopyEqualsTheShaderFolder) {
  size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(kSourceShaders)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".glsl" && ext != ".vert" && ext != ".frag" && ext != ".comp") continue;
    const fs::path rel = e.path().lexically_relative(kSourceShaders);
    const auto embedded = gl::readShaderFile(gl::embeddedShaderRoot() / rel);
    ASSERT_TRUE(embedded.has_value()) << rel;
    EXPECT_EQ(*embedded, slurp(e.path())) << rel;
    ++n;
  }
  EXPECT_GT(n, 10u);
  EXPECT_FALSE(gl::readShaderFile(gl::embeddedShaderRoot() / "passes" / "no_such.comp"));
}

// Without HV_SHADER_DIR or setShaderDir, programs expand from the embedded copy: includes resolve
// inside it and diagnostics name its virtual paths.
TEST(ShaderFiles, DefaultRootIsTheEmbeddedCopy) {
  DefaultRoot guard;
  EXPECT_EQ(gl::shaderRoot(), gl::embeddedShaderRoot());
  const auto src = gl::expandShader(gl::shaderRoot() / "passes" / "light_shade.comp", {});
  EXPECT_NE(src.text.find("#version"), std::string::npos);
  bool brdf = false;
  for (const auto& f : src.files) {
    EXPECT_EQ(f.rfind(gl::embeddedShaderRoot().string(), 0), 0u) << f;
    brdf = brdf || f.find("common/brdf.glsl") != std::string::npos;
  }
  EXPECT_TRUE(brdf);  // the include of ../common/brdf.glsl resolved inside the embedded tree
}

// HV_SHADER_DIR beats setShaderDir, which beats the embedded copy; a folder without passes/ and
// common/ is refused with its name.
TEST(ShaderFiles, FolderPrecedence) {
  DefaultRoot guard;
  gl::setShaderDir(kSourceShaders);
  EXPECT_EQ(gl::shaderRoot(), kSourceShaders);
  ::setenv("HV_SHADER_DIR", "/elsewhere", 1);
  EXPECT_EQ(gl::shaderRoot(), fs::path("/elsewhere"));
  ::unsetenv("HV_SHADER_DIR");
  try {
    gl::setShaderDir(fs::temp_directory_path());
    FAIL() << "a folder without shaders must be refused";
  } catch (const gl::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find(fs::temp_directory_path().string()), std::string::npos);
  }
  EXPECT_EQ(gl::shaderRoot(), kSourceShaders);  // unchanged by the refused call
}
