#include "halfvec/gl/log.hpp"

#include <cstdio>
#include <mutex>

namespace hv::log {
namespace {
std::mutex g_mutex;
Sink g_sink;
Level g_min = Level::Info;
const char* name(Level l) {
  switch (l) {
    case Level::Debug:
      return "debug";
    case Level::Info:
      return "info";
    case Level::Warning:
      return "warning";
    case Level::Error:
      return "error";
  }
  return "?";
}
}  // namespace

void write(Level level, std::string_view message) {
  std::lock_guard lock(g_mutex);
  if (g_sink) {
    g_sink(level, message);
    return;
  }
  if (level < g_min) return;
  std::fprintf(stderr, "halfvec %s: %.*s\n", name(level), static_cast<int>(message.size()),
               message.data());
}

Sink setSink(Sink sink) {
  std::lock_guard lock(g_mutex);
  Sink old = std::move(g_sink);
  g_sink = std::move(sink);
  return old;
}

void setMinLevel(Level level) {
  std::lock_guard lock(g_mutex);
  g_min = level;
}

}  // namespace hv::log
