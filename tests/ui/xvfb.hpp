// Xvfb for the viewer's window tests: a server per test, on a display the server picks.
#pragma once

#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#if HV_HAVE_XLIB
#include <X11/Xlib.h>
#include <X11/keysym.h>
#endif

namespace hv::test {

// prefix + n + suffix (appending: GCC 12's -Wrestrict misfires on "literal" + std::string&&).
inline std::string numbered(const char* prefix, int n, const char* suffix = "") {
  std::string s(prefix);
  s += std::to_string(n);
  s += suffix;
  return s;
}

inline std::string findXvfb() {
  for (const char* p : {"/usr/bin/Xvfb", "/usr/local/bin/Xvfb"}) {
    if (access(p, X_OK) == 0) return p;
  }
  return {};
}

// Starts Xvfb on a free display and stops it on destruction. The server picks the display itself
// (`-displayfd`: it takes the display's lock atomically and writes the number it got to the pipe),
// so two tests starting servers at the same time (ctest -j2) never share one. Choosing the number
// here from the lock files raced: both tests could see :90 free, one server then failed, and its
// test ran its viewer on the other test's server, which could be stopped under it (the likely
// cause of a viewer test that exited 1, rarely, under ctest -j2).
class Xvfb {
 public:
  explicit Xvfb(const std::string& exe) {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      close(fds[0]);
      std::freopen("/dev/null", "w", stdout);
      std::freopen("/dev/null", "w", stderr);
      // Xvfb is a system program, not the code under test: under scripts/sanitize.sh LD_PRELOAD
      // carries the ASan runtime, with which Xvfb's keymap compiler (xkbcomp, run at start-up)
      // reports its own leaks and fails, and the server never comes up. The viewer started on it
      // keeps the sanitizers (its environment is the test's).
      unsetenv("LD_PRELOAD");
      const std::string fd = std::to_string(fds[1]);
      execl(exe.c_str(), exe.c_str(), "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24",
            "-nolisten", "tcp", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    if (pid_ < 0) {
      close(fds[0]);
      return;
    }
    // Up to 10 s for the display number ("N\n"); EOF when the server died.
    std::string number;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < deadline) {
      pollfd p{fds[0], POLLIN, 0};
      if (poll(&p, 1, 100) <= 0) continue;
      char c = 0;
      if (read(fds[0], &c, 1) != 1) break;
      if (c == '\n') {
        if (!number.empty()) display_ = ":" + number;
        break;
      }
      number += c;
    }
    close(fds[0]);
    if (display_.empty()) stop();
  }
  ~Xvfb() { stop(); }
  const std::string& display() const { return display_; }

 private:
  void stop() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
    pid_ = -1;
  }
  pid_t pid_ = -1;
  std::string display_;
};

// The window tests: skipped without Xvfb or the halfvec binary; an Xvfb server per test.
class ViewerWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string xvfb = findXvfb();
    if (xvfb.empty()) GTEST_SKIP() << "Xvfb not installed (apt-get install xvfb)";
    if (access(exe.c_str(), X_OK) != 0) GTEST_SKIP() << exe << " not built";
    server = std::make_unique<Xvfb>(xvfb);
    ASSERT_FALSE(server->display().empty()) << "could not start Xvfb";
  }
  const std::string exe = std::string(HV_BINARY_DIR) + "/halfvec";
  std::unique_ptr<Xvfb> server;
};

#if HV_HAVE_XLIB
// The viewer's top-level window (no window manager under Xvfb: a child of the root), or 0.
inline Window findViewerWindow(Display* d) {
  Window root = DefaultRootWindow(d), parent = 0, *children = nullptr;
  unsigned int n = 0;
  Window found = 0;
  if (!XQueryTree(d, root, &root, &parent, &children, &n)) return 0;
  for (unsigned int i = 0; i < n && !found; ++i) {
    char* name = nullptr;
    if (XFetchName(d, children[i], &name) && name) {
      if (std::string(name).rfind("halfvec view", 0) == 0) found = children[i];
      XFree(name);
    }
  }
  if (children) XFree(children);
  return found;
}

// Sends `keysym` to `win` as the keyboard would: a press and, when `release`, its release right
// after (both reach the viewer between two of its frames).
inline void sendKey(Display* d, Window win, KeySym keysym, bool release) {
  XKeyEvent ev{};
  ev.display = d;
  ev.window = win;
  ev.root = DefaultRootWindow(d);
  ev.time = CurrentTime;
  ev.same_screen = True;
  ev.keycode = XKeysymToKeycode(d, keysym);
  ev.type = KeyPress;
  XSendEvent(d, win, True, KeyPressMask, reinterpret_cast<XEvent*>(&ev));
  if (release) {
    ev.type = KeyRelease;
    XSendEvent(d, win, True, KeyReleaseMask, reinterpret_cast<XEvent*>(&ev));
  }
  XFlush(d);
}
#endif

}  // namespace hv::test
