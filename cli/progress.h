// Long library calls on a worker thread, with a progress bar on stderr drawn
// by the main thread from the isoform_progress sink (the library only
// stores into the sink and never calls back from its workers; callers poll
// it).
#pragma once

#include <functional>

#include <CLI/App.hpp>

#include "isoform.h"

namespace isoform::cli {

struct ProgressOptions {
  bool force = false;  // --progress: draw the bar even when stderr is not a terminal
  bool quiet = false;  // --quiet: no bar and no notes on stderr (errors still print)
};

// Registers --progress and --quiet (mutually exclusive) on app.
void add_progress_flags(CLI::App& app, ProgressOptions& options);

// Runs call(progress) on a worker thread and polls progress every ~100 ms.
// The bar appears once the call has run ~0.5 s and stderr is a terminal
// (at once with force; never with quiet) and is erased at the end. Ctrl-C
// (or SIGTERM) sets the cancel flag, so the library stops and leaves nothing
// behind; an interrupt the call did not act on fails the command too.
// Throws Failure with the worker thread's isoform_last_error() on failure.
void run_with_progress(const std::function<isoform_status(isoform_progress*)>& call,
                       const ProgressOptions& options);

}  // namespace isoform::cli
