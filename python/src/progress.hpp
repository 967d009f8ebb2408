// The precomputation's progress from Python: a callable progress(levels_done, levels), called
// after each tree level, where Ctrl-C is also let in.
#pragma once

#include <utility>

#include "bindings.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc::python {

/// Runs `precompute(report)` without the GIL; `report` calls `progress` (None or a callable)
/// after each level, on the calling thread, and passes on what it raises (KeyboardInterrupt
/// included), which stops the precomputation.
template <typename Precompute>
auto precompute_with(const py::object& progress, Precompute&& precompute) {
  // Work items finish on every thread; the levels on the caller's (outside the parallel loop).
  int levels_done = 0;
  const PrecomputeProgress report = [&progress, &levels_done](const PrecomputeStatus& status) {
    if (status.levels_done == levels_done) return;
    levels_done = status.levels_done;
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!progress.is_none()) progress(status.levels_done, status.levels);
  };
  py::gil_scoped_release release;
  return std::forward<Precompute>(precompute)(report);
}

}  // namespace sscc::python
