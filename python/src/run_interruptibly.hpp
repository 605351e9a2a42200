// python/src/run_interruptibly.hpp: runs an engine call without the GIL, so that other Python
// threads go on, while Ctrl-C (and a Python progress callback's exception) still stops it.
//
// The engine calls Options::progress every kProgressInterval simplices; there the GIL is taken
// back for a moment to run Python's signal handlers and the user's callback. An exception
// raised there is kept, the engine is abandoned by a C++ exception that holds no Python
// object (it unwinds without the GIL), and the Python exception is raised again once the GIL
// is held.
#pragma once

#include <pybind11/pybind11.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <utility>

namespace drange::python {

namespace py = pybind11;

class PythonProgress {
 public:
  explicit PythonProgress(py::object callback) : callback_(std::move(callback)) {}

  // The engine's progress hook; it refers to this object, which must outlive the run.
  std::function<void(std::size_t)> hook() {
    return [this](std::size_t simplices) { report(simplices); };
  }

  // Runs `work` without the GIL; rethrows a Python exception raised during the progress calls.
  template <class Work>
  auto run(Work&& work) -> decltype(work()) {
    bool abandoned = false;
    decltype(work()) result{};
    {
      py::gil_scoped_release release;
      try {
        result = work();
      } catch (const Abandoned&) {
        abandoned = true;
      }
    }
    if (abandoned) throw std::move(*error_);
    return result;
  }

 private:
  struct Abandoned {};

  void report(std::size_t simplices) {
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!callback_.is_none()) callback_(simplices);
    } catch (py::error_already_set& e) {
      error_ = std::make_unique<py::error_already_set>(std::move(e));
      throw Abandoned{};
    }
  }

  py::object callback_;
  std::unique_ptr<py::error_already_set> error_;
};

}  // namespace drange::python
