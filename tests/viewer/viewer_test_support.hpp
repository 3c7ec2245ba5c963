#pragma once
// Shared by the viewer suites: one device per process, and stepping the real
// viewer until something happens.
#include <chrono>
#include <sdfrt/device.hpp>
#include <thread>

#include "viewer/viewer.hpp"

namespace sdfc::viewer::test {

inline sdfrt::Device& device() {
  static sdfrt::Device d = sdfrt::open_device();
  return d;
}

// Steps until done() (a reload, a build, a frame), or a minute and a half.
template <class Done>
bool step_until(Viewer& v, Done done) {
  auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(90)) {
    v.step();
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

}  // namespace sdfc::viewer::test
