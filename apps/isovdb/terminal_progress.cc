// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "terminal_progress.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>

namespace isovdb::cli {

namespace {
constexpr std::chrono::milliseconds kQuietPeriod{1000};  // stages shorter than this print nothing

std::atomic<int> gInterruptSignal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void onInterruptSignal(int signal) {
  gInterruptSignal.store(signal, std::memory_order_relaxed);
  std::signal(signal, SIG_DFL);  // the second one ends the process
}
}  // namespace

void installInterruptSignals() {
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction action {};
    action.sa_handler = onInterruptSignal;
    sigemptyset(&action.sa_mask);
    sigaction(signal, &action, nullptr);
  }
}

int interruptSignal() { return gInterruptSignal.load(std::memory_order_relaxed); }

TerminalProgress::TerminalProgress(bool enabled) : enabled_(enabled), tty_(::isatty(STDERR_FILENO) != 0) {}

void TerminalProgress::start(const char* name) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  stages_.push_back({name ? name : "working", std::chrono::steady_clock::now()});
}

void TerminalProgress::end() {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  if (stages_.empty()) return;
  const Stage& stage = stages_.back();
  const auto elapsed = std::chrono::steady_clock::now() - stage.start;
  if (stage.shown || elapsed >= kQuietPeriod) {
    std::fprintf(stderr, "%s%s: done in %.1f s\n", tty_ ? "\r\033[K" : "", stage.name.c_str(),
                 std::chrono::duration<double>(elapsed).count());
  }
  stages_.pop_back();
}

bool TerminalProgress::wasInterrupted(int percent) {
  if (interruptSignal() != 0) return true;
  if (!enabled_ || percent < 0) return false;
  std::lock_guard lock(mutex_);
  if (stages_.empty()) return false;
  Stage& stage = stages_.back();
  if (std::chrono::steady_clock::now() - stage.start < kQuietPeriod) return false;
  // On a terminal redraw one line; in a log print every 10%.
  const int step = tty_ ? 1 : 10;
  if (percent / step == stage.lastPercent / step && stage.lastPercent >= 0) return false;
  stage.lastPercent = percent;
  stage.shown = true;
  if (tty_)
    std::fprintf(stderr, "\r\033[K%s: %3d%%", stage.name.c_str(), percent);
  else
    std::fprintf(stderr, "%s: %d%%\n", stage.name.c_str(), percent);
  std::fflush(stderr);
  return false;
}

}  // namespace isovdb::cli
