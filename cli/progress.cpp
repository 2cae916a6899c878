// The progress bar and the worker thread of long library calls.
#include "progress.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <future>
#include <string>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cli.h"

namespace isoform::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Short enough that the bar looks live, long enough to cost nothing.
constexpr auto kPollInterval = std::chrono::milliseconds(100);
// Calls that end sooner than this would only flash a bar.
constexpr double kBarDelaySeconds = 0.5;
constexpr int kBarWidth = 30;

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) { g_interrupted = 1; }

// Routes Ctrl-C (and a termination request) to the cancel flag while a
// call runs, then restores the previous handlers, so an interrupt outside a
// long call still ends the process at once.
class InterruptGuard {
 public:
  InterruptGuard()
      : previous_int_(std::signal(SIGINT, on_interrupt)), previous_term_(std::signal(SIGTERM, on_interrupt)) {
    g_interrupted = 0;
  }
  ~InterruptGuard() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  void (*previous_int_)(int);
  void (*previous_term_)(int);
};

const char* stage_name(int stage) {
  switch (stage) {
    case ISOFORM_STAGE_LOAD: return "load";
    case ISOFORM_STAGE_CONTOUR: return "contour";
    case ISOFORM_STAGE_MERGE: return "merge";
    case ISOFORM_STAGE_TOPOLOGY: return "topology";
    case ISOFORM_STAGE_DONE: return "done";
    case ISOFORM_STAGE_COMPARE: return "compare";
    case ISOFORM_STAGE_CURVATURE: return "curvature";
    case ISOFORM_STAGE_REDUCE: return "reduce";
    case ISOFORM_STAGE_PATCH: return "patch";
    default: return "start";
  }
}

class ProgressBar {
 public:
  explicit ProgressBar(const ProgressOptions& options)
      : terminal_(isatty(fileno(stderr)) != 0),
        enabled_(!options.quiet && (options.force || terminal_)),
        delay_(options.force ? 0.0 : kBarDelaySeconds) {}

  void draw(const isoform_progress& progress, double elapsed) {
    if (!enabled_ || elapsed < delay_) return;
    float fraction = progress.fraction;
    fraction = fraction < 0.f ? 0.f : (fraction > 1.f ? 1.f : fraction);
    const int filled = int(fraction * kBarWidth + 0.5f);
    const std::string bar = std::string(size_t(filled), '#') + std::string(size_t(kBarWidth - filled), '-');
    std::fprintf(stderr, "\r%-9s [%s] %3d%%", stage_name(progress.stage), bar.c_str(),
                 int(fraction * 100.f));
    std::fflush(stderr);
    drawn_ = true;
  }

  // A terminal gets the line erased so the summary starts clean; a log file
  // (forced bar) keeps what was drawn and gets a newline.
  void finish() {
    if (!drawn_) return;
    if (terminal_)
      std::fprintf(stderr, "\r%*s\r", kBarWidth + 20, "");
    else
      std::fputc('\n', stderr);
    std::fflush(stderr);
  }

 private:
  bool terminal_;
  bool enabled_;
  double delay_;
  bool drawn_ = false;
};

struct Outcome {
  isoform_status status = ISOFORM_OK;
  std::string error;  // isoform_last_error() of the worker thread
};

}  // namespace

void add_progress_flags(CLI::App& app, ProgressOptions& options) {
  CLI::Option* force = app.add_flag(
      "--progress", options.force, "Draw the progress bar even when stderr is not a terminal");
  CLI::Option* quiet =
      app.add_flag("-q,--quiet", options.quiet, "No progress bar and no notes on stderr");
  force->excludes(quiet);
}

void run_with_progress(const std::function<isoform_status(isoform_progress*)>& call,
                       const ProgressOptions& options) {
  isoform_progress progress{};
  InterruptGuard interrupt_guard;
  ProgressBar bar(options);
  const Clock::time_point start = Clock::now();
  // The message is thread-local: read it on the thread that failed.
  std::future<Outcome> outcome = std::async(std::launch::async, [&call, &progress] {
    Outcome result;
    result.status = call(&progress);
    if (result.status != ISOFORM_OK) result.error = isoform_last_error();
    return result;
  });
  while (outcome.wait_for(kPollInterval) != std::future_status::ready) {
    if (g_interrupted) progress.cancel = 1;
    bar.draw(progress, std::chrono::duration<double>(Clock::now() - start).count());
  }
  bar.finish();
  const Outcome result = outcome.get();
  if (result.status == ISOFORM_ERR_CANCELLED) throw Failure(result.error, kInterruptedExitCode);
  if (result.status != ISOFORM_OK) throw Failure(result.error);
  // A call that never looked at the flag (an unchanged copy's checks, say)
  // still ends the command: nothing after it runs, nothing is written.
  if (g_interrupted) throw Failure("interrupted", kInterruptedExitCode);
}

}  // namespace isoform::cli
