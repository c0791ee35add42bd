// GPU timing of passes with timestamp queries, and debug groups so a pass has a name in
// RenderDoc/apitrace. Results are read after the frame (waiting for the GPU).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "halfvec/gl/objects.hpp"

namespace hv::gl {

class PassTimer {
 public:
  void begin(const std::string& pass);
  void end();
  // Waits for the queries of this frame; returns (pass, GPU ms) in submission order and resets.
  std::vector<std::pair<std::string, double>> resolve();
  // With `on`, end() waits for the pass's commands to complete (glFinish) before its end
  // timestamp. On an implementation that defers rasterization until later commands need the
  // result (Mesa's llvmpipe bins draws and rasterizes at the next flush), a raster pass's work
  // would otherwise be timed in the compute pass that follows it. For benchmarks only: it stalls
  // the CPU at every pass.
  void setFinishEachPass(bool on) { finish_each_pass_ = on; }

 private:
  struct Entry {
    std::string name;
    Query start, stop;
  };
  std::vector<Entry> entries_;
  std::vector<Query> pool_;
  bool finish_each_pass_ = false;
  Query take();
};

// RAII scope for one pass: debug group + timing.
class ScopedPass {
 public:
  ScopedPass(PassTimer& timer, const std::string& name);
  ~ScopedPass();
  ScopedPass(const ScopedPass&) = delete;
  ScopedPass& operator=(const ScopedPass&) = delete;

 private:
  PassTimer& timer_;
};

// Routes KHR_debug messages to hv::log (needs a debug context for full output).
void installDebugOutput();
// Also calls `handler` with every GL_DEBUG_TYPE_ERROR message (API errors; shader compiler
// messages excluded, ShaderError carries them), in the thread that made the failing call (the
// output is synchronous). The test binaries turn each into a test failure (tests/gl_errors.cpp).
// An empty function removes it.
void setDebugErrorHandler(std::function<void(const std::string&)> handler);

}  // namespace hv::gl
