#pragma once
/// \file interrupt.hpp
/// \brief Where a long computation may be stopped by its caller: the Python
/// module asks Python whether Ctrl-C was pressed (docs/python.md, "Ctrl-C"),
/// as Python itself would between two statements; the CLI sets nothing, and
/// a terminal's Ctrl-C ends the process.

namespace pendulum {

/// What check_interrupt() throws when the caller asked to stop: not a
/// std::exception, so that no handler of errors takes it for one (a batch
/// turns those into a failed line).
struct Interrupted {};

/// Asked at the checks: whether to stop. Called from the thread that set it.
using InterruptRequested = bool (*)();

/// For its lifetime, the calling thread's checks ask `requested`; the
/// previous one is restored after. The other threads' checks ask nothing.
class InterruptScope {
 public:
  explicit InterruptScope(InterruptRequested requested);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  InterruptRequested previous_;
};

/// Throws Interrupted where the calling thread's InterruptScope says to
/// stop. Without a scope a check costs a test; within one, a clock's
/// reading, and `requested` is asked at most every kInterruptPeriod
/// seconds: a check may sit in a loop of cheap steps (a table's row, an
/// observation's output, a batch of draws).
inline constexpr double kInterruptPeriod = 0.02;  // (s)
void check_interrupt();

}  // namespace pendulum
