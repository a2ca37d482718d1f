// SPDX-License-Identifier: GPL-3.0-or-later
// A stop request reaching into report writing: `gridfree run`/`daemon`/
// `report` pass their SIGINT/SIGTERM flag as a StopRequested; the writer
// polls it between charts and while a chart converter runs, and throws
// ReportInterrupted (after killing the converter and removing its
// temporary file), so a stop never waits for a report. The files written
// before the stop are complete (each is written atomically); report.md and
// report.html, written last, stay as they were; the next write of the
// report (the next run, `gridfree report`) completes it.
#pragma once

#include <functional>
#include <stdexcept>

namespace gridfree {

using StopRequested = std::function<bool()>;

class ReportInterrupted : public std::runtime_error {
 public:
  ReportInterrupted() : std::runtime_error("interrupted by a stop request") {}
};

}  // namespace gridfree
