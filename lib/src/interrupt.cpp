#include "pendulum/interrupt.hpp"

#include <chrono>

namespace pendulum {

namespace {

using Clock = std::chrono::steady_clock;

thread_local InterruptRequested current = nullptr;
thread_local Clock::time_point last_asked{};

}  // namespace

InterruptScope::InterruptScope(InterruptRequested requested) : previous_(current) {
  current = requested;
  last_asked = Clock::now();
}

InterruptScope::~InterruptScope() { current = previous_; }

void check_interrupt() {
  if (!current) return;
  const Clock::time_point now = Clock::now();
  if (std::chrono::duration<double>(now - last_asked).count() < kInterruptPeriod) return;
  last_asked = now;
  if (current()) throw Interrupted();
}

}  // namespace pendulum
