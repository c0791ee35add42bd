// A tiny leveled logger: lines go to stderr, prefixed with the level. Tests may install a sink.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace hv::log {

enum class Level { Debug, Info, Warning, Error };

using Sink = std::function<void(Level, std::string_view)>;

void write(Level level, std::string_view message);
// Replaces the sink (nullptr restores stderr). Returns the previous one.
Sink setSink(Sink sink);
void setMinLevel(Level level);

inline void debug(std::string_view m) {
  write(Level::Debug, m);
}
inline void info(std::string_view m) {
  write(Level::Info, m);
}
inline void warn(std::string_view m) {
  write(Level::Warning, m);
}
inline void error(std::string_view m) {
  write(Level::Error, m);
}

}  // namespace hv::log
