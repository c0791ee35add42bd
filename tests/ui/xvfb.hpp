// Xvfb for the viewer's window tests: a server per test on the first free display from :90.
#pragma once

#include <gtest/gtest.h>

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

// Starts Xvfb on the first free display from :90; stops it on destruction.
class Xvfb {
 public:
  explicit Xvfb(const std::string& exe) {
    for (int d = 90; d < 140; ++d) {
      if (std::filesystem::exists(numbered("/tmp/.X11-unix/X", d)) ||
          std::filesystem::exists(numbered("/tmp/.X", d, "-lock"))) {
        continue;
      }
      const std::string disp = numbered(":", d);
      pid_ = fork();
      if (pid_ == 0) {
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        execl(exe.c_str(), exe.c_str(), disp.c_str(), "-screen", "0", "1280x1024x24", "-nolisten",
              "tcp", static_cast<char*>(nullptr));
        _exit(127);
      }
      for (int i = 0; i < 100; ++i) {  // up to 10 s for the socket
        if (std::filesystem::exists(numbered("/tmp/.X11-unix/X", d))) {
          display_ = disp;
          return;
        }
        int status = 0;
        if (waitpid(pid_, &status, WNOHANG) == pid_) {  // died (display taken meanwhile?)
          pid_ = -1;
          break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
      stop();
    }
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
