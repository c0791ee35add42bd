// Linked into every test binary that creates a GL context (tests/CMakeLists.txt, hv_test ... GL):
// every GL_DEBUG_TYPE_ERROR message the driver sends (an API call with invalid arguments, ...)
// fails the test that made the call, with the message. Contexts are created with KHR_debug on
// and synchronous output (halfvec/platform/context.hpp), so the failure lands in the right test.
#include <gtest/gtest.h>

#include "halfvec/gl/timer.hpp"

namespace {
const bool kInstalled = [] {
  hv::gl::setDebugErrorHandler(
      [](const std::string& message) { ADD_FAILURE() << "GL_DEBUG_TYPE_ERROR: " << message; });
  return true;
}();
}  // namespace
