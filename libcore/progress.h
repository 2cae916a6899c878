// The library side of isoform_progress: relaxed atomic stores of the
// fraction and stage, and polls of the caller's cancel flag.
#pragma once

#include "isoform.h"

namespace isoform {

class Progress {
 public:
  explicit Progress(isoform_progress* sink) : sink_(sink) {}
  void stage(isoform_stage s) const {
    if (!sink_) return;
    __atomic_store_n(&sink_->stage, int(s), __ATOMIC_RELAXED);
    float zero = 0.0f;
    __atomic_store(&sink_->fraction, &zero, __ATOMIC_RELAXED);
  }
  void fraction(float f) const {
    if (sink_) __atomic_store(&sink_->fraction, &f, __ATOMIC_RELAXED);
  }
  bool cancelled() const { return sink_ && __atomic_load_n(&sink_->cancel, __ATOMIC_RELAXED) != 0; }

 private:
  isoform_progress* sink_;
};

}  // namespace isoform
